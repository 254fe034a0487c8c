/* source_revision.c - the one object that holds the build's revision, from
 * the bs_revision.h that make writes at every build: a commit recompiles
 * this file alone. The programs that publish the revision (the CLI, the
 * libraries, the bindings) are relinked with it; the test programs link it
 * order-only and keep the revision of their last link (Makefile). */
#include "source_revision.h"
#include "bs_revision.h"

const char *source_revision(void)
{
    return BS_REVISION;
}
