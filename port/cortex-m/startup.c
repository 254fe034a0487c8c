/* startup.c - vector table, reset and fault handling for bare-metal images under QEMU.
 *
 * Works with cm.ld and newlib's rdimon (semihosting) C library, linked with -nostartfiles
 * (this file replaces rdimon's crt0 and the toolchain's crti/crtn). Reset: enable the FPU if
 * the image uses one, zero .bss, run the C runtime init tables, open stdin/stdout/stderr over
 * semihosting, then exit(main()): stdio is flushed and main's return value becomes QEMU's
 * exit status.
 *
 * Every other exception is a fault here: the handler prints "*** CPU fault: ..." and makes
 * QEMU exit with status 99. It talks to the semihosting host directly instead of calling
 * exit(): newlib picks SYS_EXIT or SYS_EXIT_EXTENDED from a feature probe done in
 * initialise_monitor_handles, and a fault before that probe sent plain SYS_EXIT, which QEMU
 * turns into exit status 0 - a crashed test reported as a pass.
 *
 * The one interrupt an image may enable is SysTick, by defining SysTick_Handler (weak here:
 * the fault handler; port/cortex-m/twin/twin_clock_systick.c defines one).
 */
#include <stdint.h>
#include <stdlib.h>

extern char __stack_top[], __bss_start__[], __bss_end__[];   /* from cm.ld */
int main(void);
void initialise_monitor_handles(void);                      /* newlib rdimon */
void __libc_init_array(void);                               /* newlib */
void _init(void);
void _fini(void);
void Reset_Handler(void);
void cm_fault_report(const uint32_t *frame, uint32_t ipsr);

/* __libc_init_array calls _init and crt0 would provide it; nothing to do here. */
void _init(void) {}
void _fini(void) {}

enum {
    SEMIHOST_SYS_WRITE0 = 0x04,         /* write a NUL-terminated string to the console */
    SEMIHOST_SYS_EXIT_EXTENDED = 0x20,  /* exit with a status, whatever was probed */
    ADP_STOPPED_APPLICATION_EXIT = 0x20026
};

static uint32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm("r0") = op;
    register const void *r1 __asm("r1") = arg;
    __asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

static char *append(char *dst, const char *text)
{
    while (*text != '\0')
        *dst++ = *text++;
    return dst;
}

static char *append_hex(char *dst, uint32_t value)
{
    dst = append(dst, "0x");
    for (int i = 7; i >= 0; i--, value >>= 4)
        dst[i] = "0123456789abcdef"[value & 0xFu];
    return dst + 8;
}

/* Reached from fault_entry with the exception frame the core pushed on the main stack
 * (r0-r3, r12, lr, pc, xpsr) and IPSR (exception number: 3 HardFault, 4 MemManage, 5 BusFault,
 * 6 UsageFault, others unexpected). CFSR (v7-M only) tells why: e.g. bit 16 UNDEFINSTR,
 * bit 17 INVSTATE, bit 19 NOCP (FPU off), bit 25 DIVBYZERO, 0x82 a precise data fault. */
__attribute__((noreturn, used)) void cm_fault_report(const uint32_t *frame, uint32_t ipsr)
{
    static const uint32_t exit_block[2] = { ADP_STOPPED_APPLICATION_EXIT, 99 };
    char msg[96];
    uint32_t exception = ipsr & 0x1FFu;
    char *p = append(msg, "*** CPU fault: exception ");
    if (exception >= 100)
        *p++ = (char)('0' + exception / 100);
    if (exception >= 10)
        *p++ = (char)('0' + exception / 10 % 10);
    *p++ = (char)('0' + exception % 10);
    p = append_hex(append(p, ", pc "), frame[6]);
#if __ARM_ARCH >= 7
    p = append_hex(append(p, ", cfsr "), *(volatile const uint32_t *)0xE000ED28u);
#endif
    p = append(p, "\n");
    *p = '\0';
    semihost_call(SEMIHOST_SYS_WRITE0, msg);
    semihost_call(SEMIHOST_SYS_EXIT_EXTENDED, exit_block);
    for (;;) {
    }
}

/* Naked: no prologue may touch the stack before MSP is read (it points at the exception frame). */
__attribute__((naked)) static void fault_entry(void)
{
    __asm volatile("mrs r0, msp\n\t"
                   "mrs r1, ipsr\n\t"
                   "bl cm_fault_report\n\t");
}

__attribute__((noreturn)) void Reset_Handler(void)
{
#ifdef __ARM_FP
    /* CPACR: full access to CP10/CP11 before any floating-point instruction runs. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm volatile("dsb\n\tisb" ::: "memory");
#endif
    for (char *p = __bss_start__; p < __bss_end__; p++)
        *p = 0;
    __libc_init_array();
    initialise_monitor_handles();
    exit(main());
}

/* An image that enables SysTick defines it; until then a SysTick exception is a fault. */
void SysTick_Handler(void) __attribute__((weak, alias("fault_entry")));

typedef void (*cm_vector)(void);

/* The 16 system exceptions; no external interrupts are enabled, so none are listed. */
__attribute__((section(".vectors"), used)) const cm_vector cm_vectors[16] = {
    (cm_vector)__stack_top,   /* initial main stack pointer */
    Reset_Handler,
    fault_entry,  /* NMI */
    fault_entry,  /* HardFault */
    fault_entry,  /* MemManage */
    fault_entry,  /* BusFault */
    fault_entry,  /* UsageFault */
    0, 0, 0, 0,   /* reserved */
    fault_entry,  /* SVCall */
    fault_entry,  /* DebugMonitor */
    0,            /* reserved */
    fault_entry,  /* PendSV */
    SysTick_Handler,
};
