/* source_revision.h - the source revision a build of the host tools states
 * (`beamslider --version`, the JSON summaries, a map's identity). */
#ifndef SOURCE_REVISION_H
#define SOURCE_REVISION_H

/* `git describe --always --dirty` of the tree built ("unknown" outside git). */
const char *source_revision(void);

#endif
