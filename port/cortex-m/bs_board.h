/* bs_board.h - services for firmware images run under QEMU (port/cortex-m).
 *
 * An image is plain C: main() runs after startup.c has set up the FPU, .bss and semihosting;
 * printf/puts (newlib nano, %f enabled) write to the host's stdout; main's return value (mod 256)
 * is QEMU's exit status, a CPU fault gives status 99.
 */
#ifndef BS_BOARD_H
#define BS_BOARD_H

/* Instruction-count marker. Does nothing; count.sh tells QEMU's insncount plugin to watch its
 * address and print "[insn] N" each time it is called, N = instructions executed since the
 * previous call. Bracket the code to measure:
 *
 *     static float (*volatile p_step)(float) = step;    // volatile: see below
 *     bs_board_mark();
 *     y = p_step(x);
 *     bs_board_mark();                                  // -> "[insn] N" for the bracket
 *     printf("step\n");                                 // label printed after the bracket
 *
 * An empty bracket counts 2 instructions (return of the first mark + call of the second); the
 * pointer load, argument set-up and call of the code under test add a few more (measure the
 * bracket around a trivial call, e.g. n = 0 iterations, and subtract). Call the code under test
 * through a volatile function pointer (or have it write a volatile): the compiler may otherwise
 * move a computation it can see into across the marker calls, and count 0. */
void bs_board_mark(void);

/* Stack measurement. bs_board_stack_paint() fills the free stack below the caller's stack
 * pointer with a pattern (at most BS_BOARD_STACK_PAINT_BYTES = 64 KiB by default, and never
 * closer than 4 KiB to the heap); bs_board_stack_used() returns how many bytes below that
 * stack pointer have been written since, i.e. the peak stack use of what ran in between:
 *
 *     bs_board_stack_paint();
 *     p_step(x);
 *     unsigned used = bs_board_stack_used();   // bytes, exact to the byte
 *
 * Call both from the same function, with nothing in between that uses stack other than the
 * code to measure (a printf there would be counted too). Neither adds to the result (they are
 * written in assembly; 0 for nothing in between). A result equal to the painted size means
 * the region overflowed (raise BS_BOARD_STACK_PAINT_BYTES): bs_board_stack_painted() is that
 * size, which the heap may have made smaller than asked. Returns 0 if never painted.
 * Painting 64 KiB takes ~82 000 instructions: keep it out of instruction-count brackets.
 * Limit: a byte written with the pattern value 0xA5 looks unwritten, so in the rare case
 * that the deepest bytes written hold 0xA5 the result is short by those bytes. */
void bs_board_stack_paint(void);
unsigned bs_board_stack_used(void);
unsigned bs_board_stack_painted(void);

#endif /* BS_BOARD_H */
