/* out_json.c - the writer of JSON (out_json.h). */
#include "out_json.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "out_text.h"

void out_json_start(out_json *j)
{
    j->root = j->at = cJSON_CreateObject();
    j->failed = j->root == NULL;
}

static void added(out_json *j, const cJSON *member)
{
    if (!member)
        j->failed = 1;
}

void out_json_text(out_json *j, const char *key, const char *text)
{
    /* at most 3 bytes of U+FFFD per byte of text */
    char *valid = j->failed ? NULL : malloc(3 * strlen(text) + 1);
    char *put = valid;
    if (!valid) {
        j->failed = 1;
        return;
    }
    while (*text) {
        const size_t n = out_text_utf8_length(text);
        if (n == 0) {
            memcpy(put, "\xef\xbf\xbd", 3); /* U+FFFD REPLACEMENT CHARACTER */
            put += 3;
            ++text;
        } else {
            memcpy(put, text, n);
            put += n;
            text += n;
        }
    }
    *put = '\0';
    added(j, cJSON_AddStringToObject(j->at, key, valid));
    free(valid);
}

int out_json_is_number(const char *text)
{
    const char *c = text;
    if (*c == '-')
        ++c;
    if (*c == '0')
        ++c;
    else if (*c >= '1' && *c <= '9')
        while (*c >= '0' && *c <= '9')
            ++c;
    else
        return 0;
    if (*c == '.') {
        if (!(*++c >= '0' && *c <= '9'))
            return 0;
        while (*c >= '0' && *c <= '9')
            ++c;
    }
    if (*c == 'e' || *c == 'E') {
        ++c;
        if (*c == '+' || *c == '-')
            ++c;
        if (!(*c >= '0' && *c <= '9'))
            return 0;
        while (*c >= '0' && *c <= '9')
            ++c;
    }
    return *c == '\0';
}

void out_json_number(out_json *j, const char *key, const char *format, double value)
{
    char text[64];
    if (j->failed)
        return;
    if (!isfinite(value)) {
        added(j, cJSON_AddNullToObject(j->at, key));
        return;
    }
    /* a bounded text: %f of 1e300 would be 300 digits */
    if (snprintf(text, sizeof text, format, value) < (int)sizeof text && out_json_is_number(text))
        added(j, cJSON_AddRawToObject(j->at, key, text));
    else
        added(j, cJSON_AddNumberToObject(j->at, key, value));
}

void out_json_int(out_json *j, const char *key, long long value)
{
    char text[32];
    snprintf(text, sizeof text, "%lld", value);
    if (!j->failed)
        added(j, cJSON_AddRawToObject(j->at, key, text));
}

void out_json_count(out_json *j, const char *key, unsigned long long value)
{
    char text[32];
    snprintf(text, sizeof text, "%llu", value);
    if (!j->failed)
        added(j, cJSON_AddRawToObject(j->at, key, text));
}

void out_json_bool(out_json *j, const char *key, int value)
{
    if (!j->failed)
        added(j, cJSON_AddBoolToObject(j->at, key, value));
}

void out_json_number_text(out_json *j, const char *key, const char *text)
{
    if (j->failed)
        return;
    if (out_json_is_number(text))
        added(j, cJSON_AddRawToObject(j->at, key, text));
    else
        out_json_text(j, key, text);
}

void out_json_open(out_json *j, const char *key)
{
    cJSON *object = j->failed ? NULL : cJSON_AddObjectToObject(j->root, key);
    added(j, object);
    if (object)
        j->at = object;
}

void out_json_close(out_json *j)
{
    j->at = j->root;
}

int out_json_finish(out_json *j, FILE *out)
{
    char *line = j->failed || !j->root ? NULL : cJSON_PrintUnformatted(j->root);
    int status = -1;
    if (line) {
        status = fputs(line, out) >= 0 && fputc('\n', out) == '\n' ? 0 : -1;
        cJSON_free(line);
    }
    cJSON_Delete(j->root);
    j->root = j->at = NULL;
    return status;
}
