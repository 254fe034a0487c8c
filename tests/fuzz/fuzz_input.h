/* fuzz_input.h - reading a libFuzzer input as a little program: bytes,
 * integers and values of bs_real chosen to reach the edges (NaN, infinities,
 * denormals, the largest values of float and double, a few ulps either side
 * of a value, raw bit patterns). A short input reads as zeros. Shared by the
 * targets that drive the core's API (fuzz_step.c, fuzz_api.c). */
#ifndef FUZZ_INPUT_H
#define FUZZ_INPUT_H

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "beamslider.h"

typedef struct input {
    const uint8_t *data;
    size_t size;
} input;

static inline unsigned take_byte(input *in)
{
    if (in->size == 0)
        return 0;
    --in->size;
    return *in->data++;
}

static inline uint64_t take_bits(input *in, int bytes)
{
    uint64_t value = 0;
    int i;
    for (i = 0; i < bytes; ++i)
        value = value << 8 | take_byte(in);
    return value;
}

static const double special_values[] = {
    (double)NAN, -(double)NAN, (double)INFINITY, -(double)INFINITY, 0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 4.0,
    1e-9, -1e-9, 1e9, DBL_MAX, -DBL_MAX, (double)FLT_MAX, -(double)FLT_MAX, DBL_MIN, 4.9406564584124654e-324,
    (double)FLT_MIN, 1.4e-45,
    1e-300, 1e300, -1e300, 1e-30, 1e30, 1e-15, 1e15, 1e38, 1e39, 1e-38, 1e-45, 3.4028235e38,
};
static const double factors[] = {
    -1.0, 0.0, 2.0, 0.5, 10.0, 0.1, 1e3, 1e-3, 1e6, 1e-6, 1e15, 1e-15, 1e30, 1e-30, 1e100, 1e-100,
    1e300, -1e300, 1.0000001, 0.9999999,
};

/* A new value for a field that holds current. */
static inline bs_real take_value(input *in, bs_real current)
{
    const unsigned how = take_byte(in);
    const unsigned which = take_byte(in);
    switch (how % 7) {
    case 0: { /* raw bit pattern */
        bs_real value;
        uint64_t bits = take_bits(in, (int)sizeof(bs_real));
#if BS_REAL_FLOAT
        uint32_t narrow = (uint32_t)bits;
        memcpy(&value, &narrow, sizeof value);
#else
        memcpy(&value, &bits, sizeof value);
#endif
        return value;
    }
    case 1:
        return (bs_real)special_values[which % (sizeof special_values / sizeof special_values[0])];
    case 2:
        return (bs_real)((double)current * factors[which % (sizeof factors / sizeof factors[0])]);
    case 3: { /* a few ulps up or down */
        bs_real value = current;
        int i;
        for (i = 0; i < (int)(which & 15) + 1; ++i)
#if BS_REAL_FLOAT
            value = nextafterf(value, which & 16 ? (float)INFINITY : -(float)INFINITY);
#else
            value = nextafter(value, which & 16 ? (double)INFINITY : -(double)INFINITY);
#endif
        return value;
    }
    case 4: /* a relative change of up to +-2 */
        return (bs_real)((double)current * (1.0 + (double)(int8_t)which / 64.0));
    case 5: /* a small integer */
        return (bs_real)(int8_t)which;
    default:
        return current;
    }
}

static inline int take_int(input *in, int current)
{
    static const int specials[] = { -1, 0, 1, 2, 3, BS_MAX_MODES - 1, BS_MAX_MODES, BS_MAX_MODES + 1,
                                    BS_SHAPE_MAX_PIECES, BS_SHAPE_MAX_PIECES + 1, 1000, INT_MAX, INT_MIN };
    const unsigned how = take_byte(in);
    switch (how % 4) {
    case 0:
        return (int)(uint32_t)take_bits(in, 4);
    case 1:
        return specials[take_byte(in) % (sizeof specials / sizeof specials[0])];
    case 2:
        return (int)(uint32_t)((uint32_t)current + (uint32_t)(int8_t)take_byte(in)); /* wraps */
    default:
        return current;
    }
}

#endif
