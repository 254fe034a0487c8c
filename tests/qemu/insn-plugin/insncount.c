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
 *              A bracket still open at exit is left out. Sums agree with the "[insn] N"
 *              lines; tests/qemu/profile.sh turns the file into a per-function table.
 * At exit it prints "[insn] total N" (all instructions of the run).
 *
 * Exactness: the counter is bumped by an inline add in front of every translated instruction
 * (not once per translation block), so an exception in the middle of a block, a semihosting
 * trap or a fault cannot make the count skip or double instructions. The mark callback is
 * registered before the inline add of the same instruction, hence "marked one excluded":
 * an empty bracket mark(); mark(); counts the `bx lr` of the first call and the `bl` of the
 * second, 2 instructions. One vCPU is assumed (all boards here have one).
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <qemu-plugin.h>

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;

static uint64_t insn_count;          /* instructions executed so far */
static uint64_t count_at_mark;       /* insn_count at the previous mark */
static uint64_t mark_vaddr = UINT64_MAX;
static uint64_t marks;               /* marks passed so far (kept for the profile) */

/* Profile (optional): counts per code address, indexed by address / 2 (Thumb). */
#define CODE_SLOTS ((4u << 20) / 2)
#define OUTSIDE CODE_SLOTS           /* one slot for everything outside the code region */
static const char *profile_path;
static uint64_t first_bracket = 1, last_bracket = UINT64_MAX;
static uint64_t *bracket_count;      /* this bracket, per slot */
static uint64_t *total_count;        /* brackets first..last, per slot */
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
    for (uint32_t slot = 0; slot <= CODE_SLOTS; slot++)
        if (total_count[slot])
            fprintf(out, "%08" PRIx64 " %" PRIu64 " %" PRIu64 "\n",
                    slot == OUTSIDE ? (uint64_t)0xffffffffu : (uint64_t)slot * 2,
                    total_count[slot], in_worst[slot]);
    fclose(out);
    free(in_worst);
}

static void on_mark(unsigned int vcpu, void *udata)
{
    (void)vcpu;
    (void)udata;
    fprintf(stderr, "[insn] %" PRIu64 "\n", insn_count - count_at_mark);
    count_at_mark = insn_count;
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
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        const uint64_t vaddr = qemu_plugin_insn_vaddr(insn);
        if (vaddr == mark_vaddr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (profile_path) {
            const uint32_t slot = vaddr / 2 < CODE_SLOTS ? (uint32_t)(vaddr / 2) : OUTSIDE;
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_profiled_exec, QEMU_PLUGIN_CB_NO_REGS,
                                                   (void *)(uintptr_t)slot);
        }
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64,
                                                   &insn_count, 1);
    }
}

static void on_run_end(qemu_plugin_id_t id, void *udata)
{
    (void)id;
    (void)udata;
    fprintf(stderr, "[insn] total %" PRIu64 "\n", insn_count);
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
            int known = number_argument(argv[i], "first", &first_bracket);
            if (known == 0)
                known = number_argument(argv[i], "last", &last_bracket);
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
        if (!bracket_count || !total_count || !touched || !worst_slot || !worst_count) {
            fprintf(stderr, "insncount: out of memory for the profile\n");
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb_translate);
    qemu_plugin_register_atexit_cb(id, on_run_end, NULL);
    return 0;
}
