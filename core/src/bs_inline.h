/* bs_inline.h - BS_INLINE: a static function the compiler is to inline.
 *
 * The step's stages are small functions for reading's sake; called from a
 * few places, GCC weighs them too big to inline, and each call then moves
 * the step's data through memory (docs/design.md 4). Where a stage must be
 * inlined for the step to cost its arithmetic, it says so; compilers without
 * the attribute treat it as a hint. */
#ifndef BS_INLINE_H
#define BS_INLINE_H

#if defined(__GNUC__)
#define BS_INLINE static inline __attribute__((always_inline))
#else
#define BS_INLINE static inline
#endif

#endif
