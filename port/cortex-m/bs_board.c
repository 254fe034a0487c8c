/* bs_board.c - instruction-count marker and stack painting for images under QEMU (bs_board.h).
 *
 * The stack functions are naked assembly, valid on ARMv6-M (Cortex-M0+) and ARMv7-M: a C
 * prologue would push registers into the very region being painted or measured, so the
 * reference would be off by the function's own frame and a small use would read as that frame.
 */
#include <stddef.h>
#include <stdint.h>

#include "bs_board.h"

#ifndef BS_BOARD_STACK_PAINT_BYTES
#define BS_BOARD_STACK_PAINT_BYTES 65536u
#endif
/* Distance kept from the heap break: the heap may grow a little (stdio buffers) while painted. */
#define BS_BOARD_HEAP_GAP 4096u

/* GCC hands Thumb-1 (v6-M) inline assembly to the assembler in the old "divided" syntax; the
 * code below is written in unified syntax, valid on every target. */
#ifdef __ARM_ASM_SYNTAX_UNIFIED__
#define BS_BOARD_ASM_BEGIN ""
#define BS_BOARD_ASM_END ""
#else
#define BS_BOARD_ASM_BEGIN ".syntax unified\n\t"
#define BS_BOARD_ASM_END ".syntax divided\n\t"
#endif

void *sbrk(ptrdiff_t increment);   /* newlib; <unistd.h> hides it under -std=c99 */

/* Internal, used by the assembly below (hence external linkage). */
__attribute__((used)) uint32_t bs_board_paint_low;     /* lowest painted address (word aligned); 0: never painted */
__attribute__((used)) uint32_t bs_board_paint_ref;     /* stack pointer of bs_board_stack_paint's caller */
__attribute__((used)) uint32_t bs_board_paint_setup(uint32_t caller_sp);

/* noinline + volatile asm with a memory clobber: the call always happens, exactly here. */
__attribute__((noinline)) void bs_board_mark(void)
{
    __asm volatile("" ::: "memory");
}

/* Chooses the region [low, caller_sp) to paint and returns low. */
uint32_t bs_board_paint_setup(uint32_t caller_sp)
{
    uint32_t heap_limit = (uint32_t)(uintptr_t)sbrk(0) + BS_BOARD_HEAP_GAP;
    uint32_t low = caller_sp > BS_BOARD_STACK_PAINT_BYTES ? caller_sp - BS_BOARD_STACK_PAINT_BYTES
                                                          : 0u;
    if (low < heap_limit)
        low = heap_limit;
    low = (low + 3u) & ~3u;
    if (low > caller_sp)
        low = caller_sp;
    bs_board_paint_ref = caller_sp;
    bs_board_paint_low = low;
    return low;
}

/* The 8 bytes pushed around the call of bs_board_paint_setup (and that function's frame) lie
 * below the caller's SP; they are dead when the loop runs and get painted like the rest. */
__attribute__((naked)) void bs_board_stack_paint(void)
{
    __asm volatile(
        BS_BOARD_ASM_BEGIN
        "mov  r0, sp\n\t"
        "push {r0, lr}\n\t"
        "bl   bs_board_paint_setup\n\t"  /* r0 = low */
        "pop  {r1, r2}\n\t"              /* r1 = caller's SP, r2 = return address */
        "mov  lr, r2\n\t"
        "movs r3, #0xA5\n\t"             /* r3 = 0xA5A5A5A5 */
        "lsls r2, r3, #8\n\t"
        "orrs r3, r2\n\t"
        "lsls r2, r3, #16\n\t"
        "orrs r3, r2\n\t"
        "1:\n\t"
        "cmp  r0, r1\n\t"
        "bhs  2f\n\t"
        "str  r3, [r0]\n\t"
        "adds r0, r0, #4\n\t"
        "b    1b\n\t"
        "2:\n\t"
        "bx   lr\n\t"
        BS_BOARD_ASM_END);
}

/* Scans up from the lowest painted word for the first one not holding the pattern, then for the
 * first changed byte in it; returns caller's SP at paint time minus that byte's address. */
__attribute__((naked)) unsigned bs_board_stack_used(void)
{
    __asm volatile(
        BS_BOARD_ASM_BEGIN
        "ldr  r0, =bs_board_paint_low\n\t"
        "ldr  r0, [r0]\n\t"
        "ldr  r1, =bs_board_paint_ref\n\t"
        "ldr  r1, [r1]\n\t"
        "movs r3, #0xA5\n\t"
        "lsls r2, r3, #8\n\t"
        "orrs r3, r2\n\t"
        "lsls r2, r3, #16\n\t"
        "orrs r3, r2\n\t"
        "1:\n\t"
        "cmp  r0, r1\n\t"
        "bhs  3f\n\t"
        "ldr  r2, [r0]\n\t"
        "cmp  r2, r3\n\t"
        "bne  2f\n\t"
        "adds r0, r0, #4\n\t"
        "b    1b\n\t"
        "2:\n\t"                         /* this word changed: find its lowest changed byte */
        "ldrb r2, [r0]\n\t"
        "cmp  r2, #0xA5\n\t"
        "bne  3f\n\t"
        "adds r0, r0, #1\n\t"
        "b    2b\n\t"
        "3:\n\t"
        "subs r0, r1, r0\n\t"
        "bx   lr\n\t"
        ".ltorg\n\t"
        BS_BOARD_ASM_END);
}

unsigned bs_board_stack_painted(void)
{
    return (unsigned)(bs_board_paint_ref - bs_board_paint_low);
}
