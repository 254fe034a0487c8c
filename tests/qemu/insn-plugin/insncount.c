/* insncount: QEMU (7.2, plugin API v1) TCG plugin counting guest instructions exactly.
 *
 * Arguments (-plugin build/cm/libinsncount.so[,mark=ADDR]):
 *   mark=ADDR  address (0x.. or decimal; the Thumb bit is ignored) of an instruction, normally
 *              the first one of bs_board_mark(). Every time it is about to execute, the plugin
 *              prints on stderr "[insn] N", N = instructions executed since the previous mark
 *              (since the start of the run for the first one), the marked one excluded.
 *   profile=PATH, first=K, last=L
 *              also attribute every instruction executed inside brackets K..L (bracket k runs
 *              from mark 2k-1 to mark 2k; default all brackets) to its address, and at exit
 *              write PATH: a line "brackets N worst B W" (N brackets profiled, the costliest
 *              is bracket B with W instructions), then one line "ADDR TOTAL WORST" per address
 *              executed (hex address; its count summed over the brackets, and in bracket B).
 *              Instructions outside the code region (4 MiB at 0) are reported at ADDR ffffffff.
 *              With cycles=1 each line has three more fields, over the profiled brackets:
 *              "ADDR TOTAL WORST BASE TAKEN FLASH": the instruction's base cycles (each), the
 *              times it was a branch taken, its data reads from the code region.
 *              A bracket still open at exit is left out. Sums agree with the "[insn] N"
 *              lines; tests/qemu/profile.sh turns the file into a per-function table.
 *   cycles=1   also estimate Cortex-M4 cycles (cycle model below): each mark line becomes
 *              "[insn] N cycles C taken T flash F", C = cycles of the instructions' base
 *              costs, T = branches taken, F = data reads from the code region (4 MiB at 0,
 *              where the images keep code and constants), all since the previous mark. An
 *              estimate for a branch refill of P cycles and W flash wait states per read is
 *              C + P T + W F. The total line gets the same fields.
 * At exit it prints "[insn] total N" (all instructions of the run).
 *
 * Exactness: the counter is bumped by an inline add in front of every translated instruction
 * (not once per translation block), so an exception in the middle of a block, a semihosting
 * trap or a fault cannot make the count skip or double instructions. The mark callback is
 * registered before the inline add of the same instruction, hence "marked one excluded":
 * an empty bracket mark(); mark(); counts the `bx lr` of the first call and the `bl` of the
 * second, 2 instructions. One vCPU is assumed (all boards here have one).
 *
 * Cycle model (cycles=1), from the Cortex-M4 Technical Reference Manual (r0p1), "Processor
 * instruction timings" and "FPU instruction set" tables; the instruction is classified from
 * QEMU's disassembly at translation time:
 *   data processing, moves, shifts, compares, IT, NOP, MUL, (S|U)MULL, (S|U)MLAL   1
 *   MLA, MLS                                                                        2
 *   SDIV, UDIV                                                                      12 (2..12)
 *   LDR*, STR* (one register), LDREX, STREX, VLDR, VSTR                             2
 *   LDRD, STRD                                                                      3
 *   LDM, STM, PUSH, POP, VLDM, VSTM, VPUSH, VPOP (N words)                          1 + N
 *   B, BL, BX, BLX, CBZ, CBNZ (+ P when taken), TBB, TBH (2, + P)                  1
 *   VADD, VSUB, VMUL, VNMUL, VNEG, VABS, VCMP, VCVT, VMOV, VMRS, VMSR               1
 *   VMLA, VMLS, VNMLA, VNMLS, VFMA, VFMS, VFNMA, VFNMS                              3
 *   VDIV, VSQRT                                                                     14
 * A branch is taken when the next translation block entered does not start where the block
 * that ends with it falls through; a write to PC (POP {..., pc}, LDR pc) counts as a branch.
 * Left out: load/store pipelining (two neighbouring single loads or stores can take 1 cycle
 * each instead of 2, so C is an upper bound there), FPU result latencies and register
 * dependencies (the M4 has no FPU forwarding stalls documented per instruction), bus
 * contention, and the early division exit. DSP and other instructions not listed cost 1.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <qemu-plugin.h>

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;

static uint64_t insn_count;          /* instructions executed so far */
static uint64_t count_at_mark;       /* insn_count at the previous mark */

/* Cycle estimate (cycles=1): running totals and their values at the previous mark. */
#define CODE_END (4u << 20)          /* the code region: code and constants ("flash") */
static int cycles_on;
static uint64_t cycle_count, taken_count, flash_count;
static uint64_t cycles_at_mark, taken_at_mark, flash_at_mark;
static uint64_t pending_fallthrough = UINT64_MAX; /* the block entered last ends in a branch
                                                      and falls through here */
static uint64_t mark_vaddr = UINT64_MAX;
static uint64_t marks;               /* marks passed so far (kept for the profile) */

/* Profile (optional): counts per code address, indexed by address / 2 (Thumb). */
#define CODE_SLOTS ((4u << 20) / 2)
#define OUTSIDE CODE_SLOTS           /* one slot for everything outside the code region */
static const char *profile_path;
static uint64_t first_bracket = 1, last_bracket = UINT64_MAX;
static uint64_t *bracket_count;      /* this bracket, per slot */
static uint64_t *total_count;        /* brackets first..last, per slot */
static uint8_t *slot_cycles;         /* cycles=1: base cycles of the instruction at each slot */
static uint64_t *slot_taken;         /* ... branches taken there, in brackets first..last */
static uint64_t *slot_flash;         /* ... data reads from the code region there */
static uint32_t *touched;            /* slots with a count in this bracket */
static uint32_t touched_n;
static uint32_t *worst_slot;         /* the costliest bracket so far: slots and counts */
static uint64_t *worst_count;
static uint32_t worst_n;
static uint64_t worst_total, worst_bracket, brackets_profiled;
static int in_bracket;

static void close_bracket(void)
{
    uint64_t sum = 0;
    for (uint32_t i = 0; i < touched_n; i++)
        sum += bracket_count[touched[i]];
    if (sum > worst_total || brackets_profiled == 0) {
        worst_total = sum;
        worst_bracket = (marks + 1) / 2;
        for (uint32_t i = 0; i < touched_n; i++) {
            worst_slot[i] = touched[i];
            worst_count[i] = bracket_count[touched[i]];
        }
        worst_n = touched_n;
    }
    for (uint32_t i = 0; i < touched_n; i++) {
        total_count[touched[i]] += bracket_count[touched[i]];
        bracket_count[touched[i]] = 0;
    }
    touched_n = 0;
    brackets_profiled++;
}

static void on_profiled_exec(unsigned int vcpu, void *udata)
{
    const uint32_t slot = (uint32_t)(uintptr_t)udata;
    (void)vcpu;
    if (in_bracket && bracket_count[slot]++ == 0)
        touched[touched_n++] = slot;
}

static void write_profile(void)
{
    FILE *out = fopen(profile_path, "w");
    uint64_t *in_worst = calloc(CODE_SLOTS + 1, sizeof *in_worst);
    if (!out || !in_worst) {
        fprintf(stderr, "insncount: cannot write the profile %s\n", profile_path);
        if (out)
            fclose(out);
        free(in_worst);
        return;
    }
    for (uint32_t i = 0; i < worst_n; i++)
        in_worst[worst_slot[i]] = worst_count[i];
    fprintf(out, "brackets %" PRIu64 " worst %" PRIu64 " %" PRIu64 "\n", brackets_profiled,
            worst_bracket, worst_total);
    for (uint32_t slot = 0; slot <= CODE_SLOTS; slot++) {
        if (!total_count[slot])
            continue;
        fprintf(out, "%08" PRIx64 " %" PRIu64 " %" PRIu64, slot == OUTSIDE ? (uint64_t)0xffffffffu : (uint64_t)slot * 2,
                total_count[slot], in_worst[slot]);
        if (cycles_on)
            fprintf(out, " %u %" PRIu64 " %" PRIu64, slot_cycles[slot], slot_taken[slot], slot_flash[slot]);
        fputc('\n', out);
    }
    fclose(out);
    free(in_worst);
}

/* What the cycle model needs of one instruction. */
typedef struct insn_class {
    unsigned cycles;   /* base cycles (without a taken branch's refill) */
    int load;          /* reads data memory */
    int writes_pc;     /* a branch or a load into PC */
} insn_class;

static int starts_with(const char *text, const char *prefix)
{
    return strncmp(text, prefix, strlen(prefix)) == 0;
}

/* Words moved by a register list "{r4, r5, lr}" or "{d8, d9}" (a D register is two). */
static unsigned list_words(const char *operands)
{
    const char *p = strchr(operands, '{');
    unsigned words = 0;
    if (!p)
        return 1;
    for (++p; *p && *p != '}'; ++p)
        if (*p == 'r' || *p == 's' || *p == 'l' || *p == 'p' || *p == 'd' || *p == 'f' || *p == 'i') {
            words += *p == 'd' ? 2 : 1;
            while (p[1] && p[1] != ',' && p[1] != '}')
                ++p;
        }
    return words ? words : 1;
}

static int in_list(const char *list, const char *mnemonic)
{
    const size_t length = strlen(mnemonic);
    for (const char *p = list; (p = strstr(p, mnemonic)) != NULL; p += length)
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0'))
            return 1;
    return 0;
}

/* Classifies the disassembly "mnemonic[.size] operands" (see the cycle model above). */
static insn_class classify(const char *disas)
{
    insn_class c = { 1, 0, 0 };
    char mnemonic[16];
    size_t n = 0;
    const char *operands = disas;

    while (*operands && *operands != ' ' && n + 1 < sizeof mnemonic)
        mnemonic[n++] = *operands++;
    mnemonic[n] = '\0';
    while (*operands == ' ')
        ++operands;
    {
        char *dot = strchr(mnemonic, '.'); /* .w, .n, .f32, ...: same timing */
        if (dot)
            *dot = '\0';
    }
    if (mnemonic[0] == 'v') {
        if (in_list("vdiv vsqrt", mnemonic))
            c.cycles = 14;
        else if (in_list("vmla vmls vnmla vnmls vfma vfms vfnma vfnms", mnemonic))
            c.cycles = 3;
        else if (in_list("vldr vstr", mnemonic))
            c.cycles = 2;
        else if (starts_with(mnemonic, "vldm") || starts_with(mnemonic, "vstm") || in_list("vpush vpop", mnemonic))
            c.cycles = 1 + list_words(operands);
        c.load = starts_with(mnemonic, "vldr") || starts_with(mnemonic, "vldm") || !strcmp(mnemonic, "vpop");
        return c;
    }
    if (in_list("ldrd strd", mnemonic)) {
        c.cycles = 3;
    } else if (starts_with(mnemonic, "ldm") || starts_with(mnemonic, "stm") || in_list("push pop", mnemonic)) {
        c.cycles = 1 + list_words(operands);
        c.writes_pc = strstr(operands, "pc}") != NULL && !starts_with(mnemonic, "st") && strcmp(mnemonic, "push");
    } else if (starts_with(mnemonic, "ldr") || starts_with(mnemonic, "str")) {
        c.cycles = 2;
        c.writes_pc = starts_with(mnemonic, "ldr") && starts_with(operands, "pc,");
    } else if (in_list("mla mls", mnemonic)) {
        c.cycles = 2;
    } else if (in_list("sdiv udiv", mnemonic)) {
        c.cycles = 12;
    } else if (in_list("tbb tbh", mnemonic)) {
        c.cycles = 2;
        c.writes_pc = 1;
    } else if (mnemonic[0] == 'b' || in_list("cbz cbnz", mnemonic)) {
        /* b, b<cond>, bl, blx, bx (and not bic, bfi, bfc) */
        c.writes_pc = !in_list("bic bics bfi bfc bkpt", mnemonic);
    } else if (starts_with(operands, "pc,") && !in_list("cmp cmn tst teq", mnemonic)) {
        c.writes_pc = 1; /* mov pc, ...; add pc, ... */
    }
    c.load = starts_with(mnemonic, "ldr") || starts_with(mnemonic, "ldm") || !strcmp(mnemonic, "pop")
             || in_list("tbb tbh", mnemonic);
    return c;
}

/* A translation block, for the taken-branch check: where it starts, and where it falls
 * through if it ends in a branch (UINT64_MAX if not). One per translation, kept for the run
 * (the images here translate a few thousand blocks). */
typedef struct block_info {
    uint64_t start, fallthrough;
    uint32_t branch_slot;            /* profile slot of the block's last instruction */
} block_info;
static uint32_t pending_slot;        /* ... of the block entered last */

/* At the entry of each translation block: was the branch that ended the previous one taken? */
static void on_block(unsigned int vcpu, void *udata)
{
    const block_info *block = udata;
    (void)vcpu;
    if (pending_fallthrough != UINT64_MAX && block->start != pending_fallthrough) {
        ++taken_count;
        if (in_bracket)
            ++slot_taken[pending_slot];
    }
    pending_fallthrough = block->fallthrough;
    pending_slot = block->branch_slot;
}

static void on_load(unsigned int vcpu, qemu_plugin_meminfo_t info, uint64_t vaddr, void *udata)
{
    (void)vcpu;
    if (!qemu_plugin_mem_is_store(info) && vaddr < CODE_END) {
        ++flash_count;
        if (in_bracket)
            ++slot_flash[(uint32_t)(uintptr_t)udata];
    }
}

static uint32_t slot_of(uint64_t vaddr)
{
    return vaddr / 2 < CODE_SLOTS ? (uint32_t)(vaddr / 2) : OUTSIDE;
}

static void print_counts(const char *label)
{
    fprintf(stderr, "[insn] %s%" PRIu64, label, insn_count - count_at_mark);
    if (cycles_on)
        fprintf(stderr, " cycles %" PRIu64 " taken %" PRIu64 " flash %" PRIu64, cycle_count - cycles_at_mark,
                taken_count - taken_at_mark, flash_count - flash_at_mark);
    fputc('\n', stderr);
}

static void on_mark(unsigned int vcpu, void *udata)
{
    (void)vcpu;
    (void)udata;
    print_counts("");
    count_at_mark = insn_count;
    cycles_at_mark = cycle_count;
    taken_at_mark = taken_count;
    flash_at_mark = flash_count;
    if (profile_path) {
        if (in_bracket)
            close_bracket();
        ++marks;
        in_bracket = marks % 2 == 1 && (marks + 1) / 2 >= first_bracket
                     && (marks + 1) / 2 <= last_bracket;
    }
}

/* Called once per translation of a block; the registrations stay with the translated code. */
static void on_tb_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    size_t n = qemu_plugin_tb_n_insns(tb);
    (void)id;
    if (cycles_on && n > 0) {
        /* the last instruction decides whether the block ends in a branch; an IT block's
         * instructions are conditional too, which the taken check covers alike */
        struct qemu_plugin_insn *last = qemu_plugin_tb_get_insn(tb, n - 1);
        char *text = qemu_plugin_insn_disas(last);
        const int branch = text && classify(text).writes_pc;
        const uint64_t start = qemu_plugin_tb_vaddr(tb);
        const uint64_t fallthrough = qemu_plugin_insn_vaddr(last) + qemu_plugin_insn_size(last);
        block_info *block = malloc(sizeof *block);
        free(text);
        if (!block) {
            fprintf(stderr, "insncount: out of memory\n");
            exit(1);
        }
        block->start = start;
        block->fallthrough = branch ? fallthrough : UINT64_MAX;
        block->branch_slot = slot_of(qemu_plugin_insn_vaddr(last));
        qemu_plugin_register_vcpu_tb_exec_cb(tb, on_block, QEMU_PLUGIN_CB_NO_REGS, block);
    }
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t vaddr = qemu_plugin_insn_vaddr(insn);
        if (vaddr == mark_vaddr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (profile_path) {
            const uint32_t slot = slot_of(vaddr);
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_profiled_exec, QEMU_PLUGIN_CB_NO_REGS,
                                                   (void *)(uintptr_t)slot);
        }
        if (cycles_on) { /* after the mark: the marked instruction counts in the next bracket */
            char *text = qemu_plugin_insn_disas(insn);
            const insn_class c = text ? classify(text) : (insn_class){ 1, 0, 0 };
            free(text);
            qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &cycle_count,
                                                       c.cycles);
            if (c.load) /* MEM_R alone never calls back in QEMU 7.2: RW, stores filtered out */
                qemu_plugin_register_vcpu_mem_cb(insn, on_load, QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_MEM_RW,
                                                 (void *)(uintptr_t)slot_of(vaddr));
            if (profile_path)
                slot_cycles[slot_of(vaddr)] = (uint8_t)c.cycles;
        }
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64,
                                                   &insn_count, 1);
    }
}

static void on_run_end(qemu_plugin_id_t id, void *udata)
{
    (void)id;
    (void)udata;
    count_at_mark = cycles_at_mark = taken_at_mark = flash_at_mark = 0;
    print_counts("total ");
    if (profile_path)
        write_profile();
}

/* "NAME=NUMBER": 1 and *value set; 0: not NAME=...; -1: a bad number (said on stderr). */
static int number_argument(const char *argument, const char *name, uint64_t *value)
{
    const size_t length = strlen(name);
    char *end;
    if (strncmp(argument, name, length) != 0 || argument[length] != '=')
        return 0;
    *value = strtoull(argument + length + 1, &end, 0);
    if (end == argument + length + 1 || *end != '\0') {
        fprintf(stderr, "insncount: bad argument '%s' (want %s=NUMBER)\n", argument, name);
        return -1;
    }
    return 1;
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv)
{
    (void)info;
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "mark=", 5) == 0) {
            char *end;
            mark_vaddr = strtoull(argv[i] + 5, &end, 0) & ~(uint64_t)1;
            if (end == argv[i] + 5 || *end != '\0') {
                fprintf(stderr, "insncount: bad argument '%s' (want mark=ADDR)\n", argv[i]);
                return -1;
            }
        } else if (strncmp(argv[i], "profile=", 8) == 0 && argv[i][8] != '\0') {
            profile_path = argv[i] + 8;
        } else {
            uint64_t flag = 0;
            int known = number_argument(argv[i], "first", &first_bracket);
            if (known == 0)
                known = number_argument(argv[i], "last", &last_bracket);
            if (known == 0 && (known = number_argument(argv[i], "cycles", &flag)) == 1)
                cycles_on = flag != 0;
            if (known == 1)
                continue;
            if (known == 0)
                fprintf(stderr, "insncount: unknown argument '%s'\n", argv[i]);
            return -1;
        }
    }
    if (profile_path) {
        if (mark_vaddr == UINT64_MAX) {
            fprintf(stderr, "insncount: profile= needs mark=\n");
            return -1;
        }
        bracket_count = calloc(CODE_SLOTS + 1, sizeof *bracket_count);
        total_count = calloc(CODE_SLOTS + 1, sizeof *total_count);
        touched = calloc(CODE_SLOTS + 1, sizeof *touched);
        worst_slot = calloc(CODE_SLOTS + 1, sizeof *worst_slot);
        worst_count = calloc(CODE_SLOTS + 1, sizeof *worst_count);
        slot_cycles = calloc(CODE_SLOTS + 1, sizeof *slot_cycles);
        slot_taken = calloc(CODE_SLOTS + 1, sizeof *slot_taken);
        slot_flash = calloc(CODE_SLOTS + 1, sizeof *slot_flash);
        if (!bracket_count || !total_count || !touched || !worst_slot || !worst_count || !slot_cycles
            || !slot_taken || !slot_flash) {
            fprintf(stderr, "insncount: out of memory for the profile\n");
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb_translate);
    qemu_plugin_register_atexit_cb(id, on_run_end, NULL);
    return 0;
}
