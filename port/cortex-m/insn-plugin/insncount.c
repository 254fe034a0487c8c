/* insncount: QEMU (7.2, plugin API v1) TCG plugin counting guest instructions exactly.
 *
 * Arguments (-plugin build/cm/libinsncount.so[,mark=ADDR]):
 *   mark=ADDR  address (0x.. or decimal; the Thumb bit is ignored) of an instruction, normally
 *              the first one of bs_board_mark(). Every time it is about to execute, the plugin
 *              prints on stderr "[insn] N", N = instructions executed since the previous mark
 *              (since the start of the run for the first one), the marked one excluded.
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

static void on_mark(unsigned int vcpu, void *udata)
{
    (void)vcpu;
    (void)udata;
    fprintf(stderr, "[insn] %" PRIu64 "\n", insn_count - count_at_mark);
    count_at_mark = insn_count;
}

/* Called once per translation of a block; the registrations stay with the translated code. */
static void on_tb_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    size_t n = qemu_plugin_tb_n_insns(tb);
    (void)id;
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        if (qemu_plugin_insn_vaddr(insn) == mark_vaddr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64,
                                                   &insn_count, 1);
    }
}

static void on_run_end(qemu_plugin_id_t id, void *udata)
{
    (void)id;
    (void)udata;
    fprintf(stderr, "[insn] total %" PRIu64 "\n", insn_count);
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
        } else {
            fprintf(stderr, "insncount: unknown argument '%s'\n", argv[i]);
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb_translate);
    qemu_plugin_register_atexit_cb(id, on_run_end, NULL);
    return 0;
}
