/* out_json.h - the one writer of JSON: every command's one-line summary on
 * standard output (run, sweep, map, map-merge, twin, twin-plant) is built
 * here, through cJSON (Debian's libcjson-dev), and nowhere with printf.
 *
 * Texts are escaped by cJSON; a byte that starts no valid UTF-8 character
 * (a scene named by a Latin-1 file name) is written as U+FFFD, so the line
 * is always UTF-8 as JSON must be. Numbers keep the formats the summaries
 * always had (README.md's example line): each is formatted with its printf
 * format and added as raw text once that text is checked to be a JSON
 * number (else it is added as cJSON formats it); a number that is not
 * finite (JSON has no NaN or infinity) is written as null.
 *
 * Usage: out_json_start, then add members (out_json_open/close for one
 * level of nested object), then out_json_finish, which prints and frees. A
 * member that could not be added (out of memory) makes finish fail.
 */
#ifndef OUT_JSON_H
#define OUT_JSON_H

#include <stdio.h>
#include <cjson/cJSON.h>

typedef struct out_json {
    cJSON *root;   /* the summary */
    cJSON *at;     /* the object members go into: root, or one opened in it */
    int failed;    /* a member could not be added */
} out_json;

void out_json_start(out_json *j);

/* Members of the object at hand. */
void out_json_text(out_json *j, const char *key, const char *text);
void out_json_number(out_json *j, const char *key, const char *format, double value);
void out_json_int(out_json *j, const char *key, long long value);
void out_json_count(out_json *j, const char *key, unsigned long long value);
void out_json_bool(out_json *j, const char *key, int value);
/* text that is a number already (a scene value's canonical text): as a
 * number if it is one in JSON's grammar, else as a text. */
void out_json_number_text(out_json *j, const char *key, const char *text);

/* Members go into a new object under key until out_json_close. */
void out_json_open(out_json *j, const char *key);
void out_json_close(out_json *j);

/* Prints the summary as one line with a newline and frees it; 0, or -1 if
 * it could not be built or written. */
int out_json_finish(out_json *j, FILE *out);

/* 1 if text is a number in JSON's grammar (RFC 8259 section 6). */
int out_json_is_number(const char *text);

#endif
