#!/usr/bin/env python3
"""make_seeds.py - writes the seed corpora of tests/fuzz/corpus/ (committed;
rerun after changing the input layout of fuzz_step.c or the scene format).

fuzz_scene: the shipped scenes and one file per class of bad input.
fuzz_step: small programs in fuzz_step.c's input layout.
Run from the repository root: python3 tests/fuzz/make_seeds.py
"""
import glob
import os

ROOT = "tests/fuzz/corpus"


def write(target, name, data):
    os.makedirs(os.path.join(ROOT, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode("latin-1")
    with open(os.path.join(ROOT, target, name), "wb") as out:
        out.write(data)


# ---- fuzz_scene --------------------------------------------------------------
for path in sorted(glob.glob("configs/*.ini")):
    with open(path, "rb") as f:
        write("fuzz_scene", os.path.basename(path)[:-4], f.read())

GOOD = ("[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n"
        "[run]\ns0 = 0.3\nt_end = 1\n")
edge = {
    "unknown_field": GOOD + "[beam]\ncolour = red\n",
    "unknown_section": GOOD + "[bogus]\nx = 1\n",
    "duplicate": GOOD + "[run]\ns0 = 0.4\n",
    "base_twice": "[scene]\nbase = mssp2023.ini\nbase = fig6.ini\n",
    "not_a_number": GOOD.replace("frequency = 124", "frequency = 12x4"),
    "nan": GOOD.replace("frequency = 124", "frequency = nan"),
    "inf": GOOD.replace("acceleration = 14", "acceleration = inf"),
    "hex_float": GOOD.replace("acceleration = 14", "acceleration = 0x1p4"),
    "out_of_range": GOOD + "[contact]\nrestitution = 1.5\n",
    "empty_value": GOOD.replace("s0 = 0.3", "s0 ="),
    "int_garbage": GOOD + "[numerics]\nmodes = 5.5\n",
    "int_huge": GOOD + "[numerics]\nmodes = 99999999999999999999\n",
    "modes_20": GOOD + "[numerics]\nmodes = 20\ndt = 1e-7\n",
    "dt_unstable": GOOD + "[numerics]\ndt = 1e-4\n",
    "dt_tiny": GOOD + "[numerics]\ndt = 1e-300\n",
    "s0_in_clamp": GOOD.replace("s0 = 0.3", "s0 = 0.01"),
    "pcs": GOOD + "[run]\nmodel = pcs\n".replace("[run]\n", "[run]\n"),
    "pcs_edge": GOOD.replace("s0 = 0.3", "s0 = 0\nmodel = pcs"),
    "locked_no_stretch": GOOD + "[slider]\nrotation = locked\n[numerics]\nstretching = off\n",
    "implicit": GOOD + "[numerics]\nintegrator = implicit\ntheta = 0.75\ndt = 1e-4\n",
    "extreme_beam": GOOD.replace("[excitation]", "[beam]\nlength = 1e300\nthickness = 1e-300\n[excitation]"),
    "extreme_stiff": GOOD.replace("[excitation]", "[beam]\nyoungs_modulus = 1e308\n[clamps]\nrotational_stiffness = 1e-308\n[excitation]"),
    "slot_too_wide": GOOD.replace("[excitation]", "[slider]\nslot_width = 1\n[excitation]"),
    "long_line": GOOD + "[scene]\ndescription = " + "x" * 300 + "\n",
    "long_text": GOOD + "[scene]\nname = " + "n" * 150 + "\n",
    "syntax": GOOD + "[beam\nlength 0.14\n",
    "indented": GOOD + "  continued line\n",
    "no_section": "dt = 1e-5\n" + GOOD,
    "missing_field": "[scene]\nbase = mssp2023.ini\n[run]\ns0 = 0.3\n",
    "missing_base": "[scene]\nbase = nowhere.ini\n",
    "base_cycle": "[scene]\nbase = self.ini\n",
    "base_abs": "[scene]\nbase = /nonexistent/dir/x.ini\n",
    "base_long": "[scene]\nbase = " + "d/" * 90 + "x.ini\n",
    "crlf_bom": "\xef\xbb\xbf" + GOOD.replace("\n", "\r\n"),
    "nul_byte": GOOD.replace("s0 = 0.3", "s0 = 0.3\x00junk"),
    "colon": GOOD.replace("s0 = 0.3", "s0: 0.3"),
    "inline_comment": GOOD.replace("s0 = 0.3", "s0 = 0.3 ; start ;x"),
    "two_files": "[scene]\nbase = b.ini\n[run]\ns0 = 0.3\nt_end = 1\n\n#@base\n"
                 "[scene]\nbase = mssp2023.ini\n[excitation]\nfrequency = 124\nacceleration = 14\n",
    "empty": "",
    # s0 = 0.8 is the host's upper edge for L = 0.05, B = 0.02 (1 - B/2L); the core refuses it
    "s0_edge": GOOD.replace("[excitation]", "[beam]\nlength = 0.05\n[slider]\nslot_width = 0.02\n"
                            "[numerics]\ndt = 5e-6\n[excitation]").replace("s0 = 0.3", "s0 = 0.8"),
    "long_beam": GOOD.replace("[excitation]", "[beam]\nlength = 0.3\n[slider]\nslot_width = 0.013\n[excitation]"),
    # the reader's line checks (docs/robustness.md section 6, "Found")
    "section_trailing": GOOD.replace("[excitation]", "[excitation] frequency = 200"),
    "section_spaces": GOOD.replace("[run]", "[ run ]"),
    "section_empty": GOOD.replace("[run]", "[]"),
    "cr_only": GOOD.replace("\n", "\r"),
    "control_char": GOOD + "[scene]\nname = a\x1bb\n",
    "no_key": GOOD + "= 0.3\n",
}
for name, text in edge.items():
    write("fuzz_scene", name, text)

# ---- fuzz_step ---------------------------------------------------------------
# head: base (bits 0-1: fig6, fig6_1mode, fig6_frictionless), PCS (bit 2),
# edits (>> 3). A value is (how, which[, raw bytes]): how 1 = special_values[which],
# 2 = current * factors[which], 5 = small integer, 6 = keep.
KEEP = [6, 0]
RUN63 = [252]                       # op 252 % 9 = 0 (run), (252 >> 3) * 2 + 1 = 63 steps
# scene edit targets: the fields of core/include/bs_scene_fields.h in order
T = {"n_modes": 0, "omega_sq": 1, "damping": 2, "stretch": 4, "length": 9, "corner": 11, "com_offset": 12,
     "mass_inv": 15, "mu": 18, "e_n": 19, "base_accel": 20, "base_displacement": 22, "dt": 24}
SOLVER = 8                          # op 8: bs_sim_set_solver(max_sweeps, tol_rel, tol_abs, measure_residual)


def head(base, pcs=False, edits=0):
    return [base | (4 if pcs else 0) | edits << 3]


def special(i):
    return [1, i]


def factor(i):
    return [2, i]


steps = [
    ("fig6_free", head(0) + KEEP + RUN63 * 16),
    ("fig6_1mode", head(1) + KEEP + RUN63 * 16),
    ("frictionless_pcs", head(2, True) + KEEP + RUN63 * 8 + [5, 1, 40] + RUN63 * 8),
    ("omega_nan", head(0, edits=1) + [T["omega_sq"], 0, 2] + special(0) + KEEP + RUN63),
    ("length_negative", head(0, edits=1) + [T["length"], 0, 0] + factor(0) + KEEP + RUN63),
    ("dt_double", head(0, edits=1) + [T["dt"], 0, 0] + factor(2) + KEEP + RUN63),
    ("modes_zero", head(0, edits=1) + [T["n_modes"], 0, 0, 1, 1] + KEEP + RUN63 * 4),
    ("mu_huge", head(0, edits=1) + [T["mu"], 0, 0] + special(13) + KEEP + RUN63 * 4),
    ("accel_huge", head(1, edits=1) + [T["base_accel"], 0, 0] + factor(8) + KEEP + RUN63 * 4),
    ("sweeps_many", head(0) + KEEP + [SOLVER, 1, 10] + KEEP + KEEP + [1, 0] + RUN63 * 4),
    ("residual_off", head(0) + KEEP + [SOLVER, 3] + KEEP + KEEP + [0, 0] + RUN63 * 4),
    ("s0_nan", head(0) + special(0) + RUN63),
    # bs_sim_init once returned BS_OK with z_C = base_displacement - com_offset = inf
    ("regress-init-z-overflow", head(0, edits=2) + [T["base_displacement"], 0, 0] + special(14)
     + [T["com_offset"], 0, 0] + special(15) + KEEP + RUN63),
    ("state_q_unstable", head(0) + KEEP + RUN63 + [3, 1, 1, 0, 0, 5, 1] + RUN63),
    ("state_velocity_huge", head(1) + KEEP + [3, 8, 1, 3, 0, 1, 23] + RUN63),
    ("state_nan", head(0) + KEEP + [4, 2, 1, 1, 0, 1, 0] + RUN63),
    ("queries_restart", head(0) + KEEP + RUN63 + [6, 7, 1, 9] + RUN63),
]
for name, data in steps:
    write("fuzz_step", name, bytes(data))
