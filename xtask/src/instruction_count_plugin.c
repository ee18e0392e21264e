/*
 * A QEMU TCG plugin that counts the guest instructions executed between three addresses, the
 * firmware's markers: `start` (`microtrace_measure_start`, before the scene is prepared),
 * `render` (`microtrace_measure_render`, between preparation and render) and `end`
 * (`microtrace_measure_end`, after the render). Every translated instruction adds one to a
 * counter inline, and the counter is noted when each marker is first reached (`render` and
 * `end` only after `start`), so the counts are exact and the same run to run. Instructions, not
 * cycles: a 12-cycle divide counts as one.
 *
 * Debian's QEMU 7.2 loads plugins but ships no qemu-plugin.h, so the few declarations of the
 * version-1 plugin API this file uses are written out below (shared/research/qemu.md,
 * "A TCG plugin").
 *
 * Arguments: start=ADDRESS,render=ADDRESS,end=ADDRESS,out=FILE. When `end` is reached, writes
 * to FILE, one `key=N` a line: frame_instructions (start to end) and, when `render` was reached
 * in between, prepare_instructions (start to render) and render_instructions (render to end),
 * which add up to the frame.
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- from qemu-plugin.h (QEMU 7.2, QEMU_PLUGIN_VERSION 1) ---- */
typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn, qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn *insn, enum qemu_plugin_op op, void *ptr,
                                                uint64_t imm);
void qemu_plugin_outs(const char *string);
#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;
/* ---- end of the API declarations ---- */

static uint64_t executed;            /* every instruction since start-up */
static uint64_t executed_at_start;   /* `executed` when `start` was first reached */
static uint64_t executed_at_render;  /* `executed` when `render` was first reached after it */
static bool started, rendering, finished;
static uint64_t start_address, render_address, end_address;
static char out_path[4096];

static void reached_start(unsigned int vcpu, void *userdata)
{
    (void)vcpu; (void)userdata;
    if (!started) {
        started = true;
        executed_at_start = executed;
    }
}

static void reached_render(unsigned int vcpu, void *userdata)
{
    (void)vcpu; (void)userdata;
    if (started && !rendering && !finished) {
        rendering = true;
        executed_at_render = executed;
    }
}

static void reached_end(unsigned int vcpu, void *userdata)
{
    (void)vcpu; (void)userdata;
    if (!started || finished) {
        return;
    }
    finished = true;
    char line[192];
    if (rendering) {
        snprintf(line, sizeof line, "frame_instructions=%llu\nprepare_instructions=%llu\nrender_instructions=%llu\n",
                 (unsigned long long)(executed - executed_at_start),
                 (unsigned long long)(executed_at_render - executed_at_start),
                 (unsigned long long)(executed - executed_at_render));
    } else {
        snprintf(line, sizeof line, "frame_instructions=%llu\n", (unsigned long long)(executed - executed_at_start));
    }
    qemu_plugin_outs(line);
    FILE *out = fopen(out_path, "w");
    if (out) {
        fputs(line, out);
        fclose(out);
    }
}

static void translated(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t count = qemu_plugin_tb_n_insns(tb);
    for (size_t i = 0; i < count; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        uint64_t address = qemu_plugin_insn_vaddr(insn);
        /* The marker callbacks are registered first, so they see the count before this
         * instruction adds itself: each count runs from one marker up to, not including, the
         * next (the `render` marker's own instructions are the render's). */
        if (address == start_address) {
            qemu_plugin_register_vcpu_insn_exec_cb(insn, reached_start, QEMU_PLUGIN_CB_NO_REGS, NULL);
        }
        if (address == render_address) {
            qemu_plugin_register_vcpu_insn_exec_cb(insn, reached_render, QEMU_PLUGIN_CB_NO_REGS, NULL);
        }
        if (address == end_address) {
            qemu_plugin_register_vcpu_insn_exec_cb(insn, reached_end, QEMU_PLUGIN_CB_NO_REGS, NULL);
        }
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &executed, 1);
    }
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    (void)info;
    bool have_start = false, have_render = false, have_end = false;
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "start=", 6) == 0) {
            start_address = strtoull(argv[i] + 6, NULL, 0);
            have_start = true;
        } else if (strncmp(argv[i], "render=", 7) == 0) {
            render_address = strtoull(argv[i] + 7, NULL, 0);
            have_render = true;
        } else if (strncmp(argv[i], "end=", 4) == 0) {
            end_address = strtoull(argv[i] + 4, NULL, 0);
            have_end = true;
        } else if (strncmp(argv[i], "out=", 4) == 0) {
            snprintf(out_path, sizeof out_path, "%s", argv[i] + 4);
        } else {
            fprintf(stderr, "instruction_count_plugin: unknown argument %s\n", argv[i]);
            return -1;
        }
    }
    if (!have_start || !have_render || !have_end || out_path[0] == 0) {
        fprintf(stderr, "instruction_count_plugin: needs start=ADDRESS,render=ADDRESS,end=ADDRESS,out=FILE\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, translated);
    return 0;
}
