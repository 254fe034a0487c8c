/* twin_source_stdio.c - the twin firmware's sample source on the host: the
 * stream file through stdio (twin_board.h). */
#include <stdio.h>
#include <string.h>
#include "twin_board.h"

static FILE *stream;

int twin_source_open(const char *path, twin_stream_header *header)
{
    stream = fopen(path, "rb");
    if (!stream)
        return -1;
    if (fread(header, sizeof *header, 1, stream) != 1 || memcmp(header->magic, TWIN_STREAM_MAGIC, 4) != 0) {
        fclose(stream);
        stream = NULL;
        return -1;
    }
    return 0;
}

uint32_t twin_source_read(twin_stream_sample *samples, uint32_t max)
{
    return stream ? (uint32_t)fread(samples, sizeof *samples, max, stream) : 0u;
}
