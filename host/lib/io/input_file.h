/* input_file.h - how every file a command reads is opened (docs/robustness.md,
 * "Files a command reads").
 *
 * A file that is read is a regular file of at most the size stated for its
 * kind (input_kinds[] in input_file.c, one table): a FIFO, a device or a
 * folder is refused before anything is read from it (it is opened with
 * O_NONBLOCK and checked with fstat, so a FIFO without a writer cannot block
 * the open), and so is a file larger than its kind may be. A live stream is
 * not a file: a command that reads one takes it from standard input
 * explicitly (`twin --measured -`), through input_lines with no size bound.
 *
 * Text is read line by line through input_lines: each line bounded, a NUL
 * byte refused (not a text file), \n or \r\n ends, the bytes read counted
 * against the kind's bound (a file that grows while it is read). The
 * readers of headed CSV files (a record, measured signals) take a line's
 * fields apart with input_skip_blanks, input_trim_end and input_number.
 */
#ifndef INPUT_FILE_H
#define INPUT_FILE_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

/* The kinds of file a command reads. */
typedef enum input_kind {
    INPUT_SCENE,        /* a scene file or one of its bases */
    INPUT_RECORD,       /* a recorded base acceleration, CSV or WAV (run --excitation) */
    INPUT_MEASURED,     /* a measured-signals file (twin --measured, twin_pack) */
    INPUT_MAP_IDENTITY, /* a map folder's map-identity.txt */
    INPUT_MAP_RESULTS,  /* a map folder's runs-*.csv */
    INPUT_MAP_TABLE,    /* a map folder's runs.csv or map.csv (map-plot) */
    INPUT_KINDS
} input_kind;

/* What a kind is called in messages ("scene file") and its size bound [bytes]. */
const char *input_kind_name(input_kind kind);
long long input_kind_max_bytes(input_kind kind);

/* Which file was opened (to find the same one again, or to tell an output
 * that would overwrite it). */
typedef struct input_identity {
    dev_t dev;
    ino_t ino;
    off_t size;
    long long mtime_ns;
} input_identity;

/* Opens path to read a file of kind: 0 with *file open (and *identity
 * filled unless NULL), or -1 with *verb "open" (it could not be opened) or
 * "read" (it is not a regular file, or too large) and the reason in why,
 * without the path: "a FIFO (named pipe), not a regular file", "2000000
 * bytes, more than a scene file may have (1048576, 1 MiB)". */
int input_file_open_why(const char *path, input_kind kind, FILE **file, input_identity *identity,
                        const char **verb, char *why, size_t why_size);

/* The same, with the whole message in err: "PATH: cannot read scene file:
 * a FIFO (named pipe), not a regular file". */
int input_file_open(const char *path, input_kind kind, FILE **file, input_identity *identity, char *err,
                    size_t err_size);

/* 1 if path names the file of identity now (same device, inode, size and
 * modification time): a second pass reads what the first one checked. */
int input_file_unchanged(FILE *file, const input_identity *identity);

/* Lines of text from an open file. */
typedef struct input_lines {
    FILE *file;
    const char *path;        /* for messages */
    long line;               /* of the line last read, from 1 */
    long long bytes;         /* read so far */
    long long max_bytes;     /* 0: no bound (standard input) */
} input_lines;

void input_lines_start(input_lines *in, FILE *file, const char *path, long long max_bytes);

/* The next line into text (at most size - 1 characters, without its \n or
 * \r\n): 1, 0 at the end of the file, -1 with "PATH:LINE: longer than N
 * characters" (N = size - 1), "PATH:LINE: a NUL byte: not a text file", a
 * read error or a file grown past its bound in err. */
int input_lines_next(input_lines *in, char *text, size_t size, char *err, size_t err_size);

/* text from its first character that is not a blank (space or tab). */
const char *input_skip_blanks(const char *text);

/* Removes text's trailing blanks, in place. */
void input_trim_end(char *text);

/* text is a finite number (strtod's syntax), then, unless unit is NULL, the
 * word unit ("10 Hz", not "10 Hzx"), blanks allowed around: 0 with *value,
 * or -1 (*value undefined). */
int input_number(const char *text, const char *unit, double *value);

#endif
