#!/usr/bin/env python3
"""make_seeds.py - writes the seed corpora of tests/fuzz/corpus/ (committed;
rerun after changing the input layout of fuzz_step.c or the scene format).

fuzz_scene: the shipped scenes and one file per class of bad input.
fuzz_step: small programs in fuzz_step.c's input layout.
fuzz_excitation, fuzz_measured, fuzz_map, fuzz_scene_set: valid files as the
commands write them and one per class of bad input (the defects of issue 26
as regress-*), in each target's input layout.
fuzz_api: small programs in fuzz_api.c's input layout, one edited checkpoint
per rule of bs_sim_restore.
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
# bs_sim_restore refused the checkpoint of a state the step produced: with
# mass_inv edited to 1.8e308 the Delassus diagonal is infinite, the pair solve
# reports a residual that is not a number (unconverged) and the step BS_OK
# (the input as fuzz_step found it)
steps.append(("regress-restore-nan-residual", list(bytes.fromhex(
    "080ffff601fcf90d0600f8f2787878fcfcfc2700fc620000000055eeffffe2e2e2e27d270000e2e2e2e2e2e2e2"
    "e2e2e2e2e2e2e2e2e2e2e2e2e20000000000000000000000000000000000000000f0fcfc0101065f5f5f5f5f5ffc"))))
for name, data in steps:
    write("fuzz_step", name, bytes(data))


# ---- fuzz_excitation -----------------------------------------------------------
# 8 bytes of options (fuzz_excitation.c), then the file. flags: bits 0-1
# --channel, bit 2 --scale given, bits 3-4 the run (0 every covered step, 1 a
# given number, 2 a given number at a tabled dt, 3 the file alone).
import math
import struct


def options(channel=0, scale=None, run=0, latency=0, k=100, steps=10, max_mean=0, dt=0):
    scale_index = {None: 0, 1.0: 0, 9.80665: 1, 1e300: 4}[scale]
    flags = channel | (4 if scale is not None else 0) | run << 3
    return bytes([flags, scale_index, latency, k & 255, k >> 8, steps - 1, max_mean, dt]).decode("latin-1")


TITLE = "# beamslider base acceleration\n"
SINE = "".join("%.6g\n" % (14 * math.sin(0.3 * j)) for j in range(40))
CSV = TITLE + "# sample_rate = 1000 Hz\n# unit = m/s^2\n" + SINE
TIMED = TITLE + "# sample_rate = 1000 Hz\n# unit = g\n# t0 = -0.005 s\n" + "".join(
    "%.6g,%.6g\n" % (-0.005 + j / 1000.0, math.cos(0.2 * j)) for j in range(40))
records = {
    "csv": options() + CSV,
    "csv_timed_g": options(k=300) + TIMED,
    "csv_latency": options(latency=3, k=50) + CSV,
    "csv_steps": options(run=1, steps=20) + CSV,
    "csv_dt_table": options(run=2, steps=30, dt=0) + CSV,
    "csv_alone": options(run=3) + CSV,
    "csv_max_mean": options(max_mean=9) + CSV,
    "csv_crlf_comments": options() + (TITLE + "# a free comment\n# sample_rate = 2 kHz\n# unit = m/s^2\n"
                                      + SINE).replace("\n", "\r\n"),
    "csv_khz": options() + CSV.replace("1000 Hz", "1 kHz"),
    "csv_rate_twice": options() + CSV.replace("# unit", "# sample_rate = 10 Hz\n# unit"),
    "csv_comment_after": options() + CSV + "# late\n1\n",
    "csv_gap": options() + TIMED.replace("0.015,", "0.017,"),
    "csv_three_values": options() + CSV + "1,2,3\n",
    # issue 26 defect 1: the step count wrapped the allocation; out-of-range conversions
    "regress-rate-wrap": options() + TITLE + "# sample_rate = 1.0842027145865592e-14 Hz\n# unit = m/s^2\n1\n2\n3\n",
    "regress-rate-denormal": options() + TITLE + "# sample_rate = 4.9e-324 Hz\n# unit = m/s^2\n1\n2\n",
    "regress-t0-huge": options() + TITLE + "# sample_rate = 100 Hz\n# unit = m/s^2\n# t0 = -1e300 s\n1\n2\n",
    # issue 26 defect 4: finite values whose step means are not
    "regress-mean-overflow": options() + TITLE + "# sample_rate = 1000 Hz\n# unit = g\n" + "1e308\n-1e308\n" * 10,
}


def riff(chunks):
    body = b"WAVE" + b"".join(name + struct.pack("<I", len(data)) + data + (b"\0" if len(data) % 2 else b"")
                              for name, data in chunks)
    return b"RIFF" + struct.pack("<I", len(body)) + body


def fmt(tag, channels, rate, bits):
    return struct.pack("<HHIIHH", tag, channels, rate, rate * channels * bits // 8, channels * bits // 8, bits)


def frames(values, bits, channels=1, is_float=False):
    out = b""
    for v in values:
        for c in range(channels):
            x = v if c == channels - 1 else -v
            if is_float:
                out += struct.pack("<f", x)
            elif bits == 16:
                out += struct.pack("<h", int(x * 32767))
            elif bits == 24:
                out += struct.pack("<i", int(x * 8388607))[:3]
            else:
                out += struct.pack("<i", int(x * 2147483647))
    return out


WAVE = [math.sin(0.25 * j) for j in range(48)]
extensible = fmt(0xFFFE, 1, 8000, 16) + struct.pack("<HHI", 22, 16, 4) + struct.pack("<H", 1) + b"\0" * 14
records.update({
    "wav16": options(scale=9.80665).encode("latin-1") + riff([(b"fmt ", fmt(1, 1, 8000, 16)), (b"data", frames(WAVE, 16))]),
    "wav24_stereo": options(channel=2, scale=9.80665).encode("latin-1") + riff([(b"fmt ", fmt(1, 2, 8000, 24)),
                                                               (b"data", frames(WAVE, 24, 2))]),
    "wav32": options(scale=9.80665, run=1, steps=40).encode("latin-1") + riff([(b"fmt ", fmt(1, 1, 4000, 32)),
                                                              (b"data", frames(WAVE, 32))]),
    "wav_float": options(scale=9.80665).encode("latin-1") + riff([(b"fmt ", fmt(3, 1, 8000, 32)), (b"data", frames(WAVE, 32, 1, True))]),
    "wav_float_huge": options(scale=1e300).encode("latin-1") + riff([(b"fmt ", fmt(3, 1, 8000, 32)),
                                                   (b"data", struct.pack("<f", 3.4e38) * 8)]),
    "wav_extensible": options(scale=9.80665).encode("latin-1") + riff([(b"fmt ", extensible), (b"data", frames(WAVE, 16))]),
    "wav_odd_chunk": options(scale=9.80665).encode("latin-1") + riff([(b"LIST", b"odd"), (b"fmt ", fmt(1, 1, 8000, 16)),
                                                    (b"data", frames(WAVE, 16))]),
    "wav_no_scale": options().encode("latin-1") + riff([(b"fmt ", fmt(1, 1, 8000, 16)), (b"data", frames(WAVE, 16))]),
    "wav_truncated": options(scale=9.80665).encode("latin-1") + riff([(b"fmt ", fmt(1, 1, 8000, 16)), (b"data", frames(WAVE, 16))])[:60],
    "wav_second_fmt": options(scale=9.80665).encode("latin-1") + riff([(b"fmt ", fmt(1, 1, 8000, 16)), (b"fmt ", fmt(1, 1, 8000, 16)),
                                                     (b"data", frames(WAVE, 16))]),
})
for name, data in records.items():
    write("fuzz_excitation", name, data)

# ---- fuzz_measured ---------------------------------------------------------------
MEASURED_HEAD = ("# beamslider measured signals (docs/twin.md, \"Observer\")\n"
                 "# plant = fig6, s0 0.3, freq_scale 1, snr inf dB, accel_snr inf dB, bits 0, seed 1\n"
                 "# sample_rate = 50000 Hz\n# signal = deflection\n# signal_unit = m\n# base_accel_unit = m/s^2\n"
                 "# latency = 0 s\n# noise = 1e-30 m\n# accel_noise = 0 m/s^2\n")
ROWS = "".join("%.6g,%.9g,%.9g,0.3\n" % ((k + 1) / 50000.0, -14 * math.cos(0.0151 * (k + 1)), 3e-9 * (k + 1) ** 2)
               for k in range(20))
MEASURED = MEASURED_HEAD + "t,base_accel,signal,s_true\n" + ROWS
NO_TRUTH = MEASURED_HEAD + "t,base_accel,signal\n" + "".join(r.rsplit(",", 1)[0] + "\n" for r in ROWS.splitlines())
measured = {
    "plant": MEASURED,
    "no_truth": NO_TRUTH,
    "voltage": MEASURED.replace("signal = deflection", "signal = voltage").replace("signal_unit = m", "signal_unit = V")
                       .replace("noise = 1e-30 m", "noise = 1e-3 V"),
    "minimal": "# beamslider measured signals\n# sample_rate = 100 Hz\n# signal = deflection\nt,base_accel,signal\n"
               "0.01,1,2\n0.02 , 3 ,4\n",
    "crlf": MEASURED.replace("\n", "\r\n"),
    "khz": MEASURED.replace("50000 Hz", "50 kHz"),
    "field_twice": MEASURED.replace("# latency", "# signal = voltage\n# latency"),
    "unknown_key": MEASURED.replace("# latency", "# colour = red\n# latency"),
    "noise_unit": MEASURED.replace("noise = 1e-30 m", "noise = 1e-30 V"),
    "unit_mismatch": MEASURED.replace("signal_unit = m", "signal_unit = V"),
    "gap": MEASURED.replace("0.0001,", "0.00012,", 1),
    "comment_after": MEASURED + "# late\n",
    "no_rows": MEASURED_HEAD + "t,base_accel,signal,s_true\n",
    "rate_tiny": MEASURED.replace("50000 Hz", "4.9e-324 Hz"),
    "nan_row": MEASURED_HEAD + "t,base_accel,signal,s_true\n2e-05,nan,1,0.3\n",
    "columns": MEASURED_HEAD + "t,base_accel,signal,s_true\n2e-05,1,2\n",
    "no_title": MEASURED.replace("# beamslider measured signals", "# beamslider measured", 1),
}
for name, text in measured.items():
    write("fuzz_measured", name, text)

# ---- fuzz_map --------------------------------------------------------------------
# One flags byte (bit 0: re-seal the result rows' checks), then the folder's
# files separated by lines "@@": map-identity.txt, runs-a.csv, runs-b.csv,
# map.csv. A map of 2 x 2 points and 2 repeats as beamslider map writes it
# (the checks computed here as map_case.c does: FNV-1a of the row up to its
# last comma).


def fnv(text):
    h = 2166136261
    for b in text.encode("latin-1"):
        h = ((h ^ b) * 16777619) & 0xffffffff
    return h


def sealed(row):
    text = row + ",0.0003,"
    return text + "%08x" % fnv(text) + "\n"


IDENTITY = ("# beamslider map: what this folder's results are of (docs/maps.md). A map command\n"
            "# whose identity differs is refused here; lines starting with info are not compared.\n"
            "format = 2\nversion = 0.8.0\nprecision = double\nfields_hash = 311d3dbfcefb7ce3\nrepeat = 2\n"
            "perturbation = 1e-05\nvary excitation.frequency = 120,124\nvary excitation.acceleration = 10,14\n"
            "info revision = e052678d82b8\ninfo scene = fig6\ninfo scene_file = configs/fig6.ini\n"
            "info set = --set run.t_end=0.02\ninfo command = beamslider map configs/fig6.ini\n")
RUNS_HEADER = ("case,point,repeat,excitation.frequency,excitation.acceleration,s0,status,outcome,s_settled,window_s,s_end,"
               "s_min,t_s_min,amp_h,amp_max_h,v_last,v_peak,cycles,power_w,energy_j,steps,unconverged_steps,"
               "max_pgs_iters,max_systems,hash,wall_s,check\n")
VALUES = [("120", "10"), ("120", "14"), ("124", "10"), ("124", "14")]
OUTCOMES = ["other", "other", "signature", "other", "fault", "other", "stop", "stop"]


def row(c):
    point, repeat = c // 2, c % 2
    f, a = VALUES[point]
    status = "ok" if OUTCOMES[c] != "fault" else "stopped"
    return ("%d,%d,%d,%s,%s,%.5g,%s,%s,0.2999%02d,0.02,0.30004,0.29991,0.016100,0.0889,0,0,0,0,nan,nan,1000,%d,1,4,d33833d5"
            % (c, point, repeat, f, a, 0.3 + 1e-5 * repeat, status, OUTCOMES[c], 40 + c, c % 3))


ROWS_A = RUNS_HEADER + "".join(sealed(row(c)) for c in range(0, 8, 2))
ROWS_B = RUNS_HEADER + "".join(sealed(row(c)) for c in range(1, 8, 2))
POINTS_HEADER = ("point,excitation.frequency,excitation.acceleration,repeats,outcome,agreement,frac_trivial,"
                 "frac_signature,frac_relaxation,frac_self_damping,frac_stop,frac_fault,frac_other,s_settled_mean,"
                 "s_settled_sd,s_settled_min,s_settled_max,amp_h_mean,amp_h_sd,v_last_mean,v_peak_mean,power_w_mean,"
                 "power_w_sd,unconverged_steps,window_s\n")
POINTS = POINTS_HEADER + "".join("%d,%s,%s,2,other,0.5,0,0.5,0,0,0,0,0.5,0.29994,2.5e-06,0.29993,0.29995,0.0889,"
                                 "0.0001,0,0,nan,nan,1,0.02\n" % (p, f, a) for p, (f, a) in enumerate(VALUES))


def folder(identity=IDENTITY, a=ROWS_A, b=ROWS_B, points=POINTS, flags=0):
    return bytes([flags]) + "@@\n".join([identity, a, b, points]).encode("latin-1")


maps = {
    "complete": folder(),
    "complete_resealed": folder(flags=1),
    "one_file": folder(a=ROWS_A + ROWS_B[len(RUNS_HEADER):], b=RUNS_HEADER),
    "half_done": folder(b=RUNS_HEADER),
    "duplicate_differing": folder(b=ROWS_B + sealed(row(0).replace("0.299940", "0.299941"))),
    "torn_last_line": folder(a=ROWS_A + row(1)),
    "invalid_check": folder(a=ROWS_A + row(1) + ",0.0003,00000000\n"),
    "case_out_of_range": folder(a=ROWS_A + sealed(row(7).replace("7,3,1", "9,3,1", 1)), flags=1),
    "identity_control": folder(identity=IDENTITY.replace("info scene = fig6", "info scene = f\x1big6")),
    "identity_format": folder(identity=IDENTITY.replace("format = 2", "format = 1")),
    "identity_repeat": folder(identity=IDENTITY.replace("repeat = 2", "repeat = 0")),
    "identity_vary_twice": folder(identity=IDENTITY + "vary excitation.frequency = 1\n"),
    "identity_value_twice": folder(identity=IDENTITY.replace("= 120,124", "= 120,120")),
    "identity_text_field": folder(identity=IDENTITY.replace("excitation.acceleration = 10,14", "scene.name = a,b")),
    "identity_choice": folder(identity=IDENTITY.replace("excitation.acceleration = 10,14", "run.model = free,pcs")),
    "identity_cut": folder(identity=IDENTITY[:-1]),
    "identity_no_repeat": folder(identity=IDENTITY.replace("repeat = 2\n", "")),
    "table_cut_short": folder(points=POINTS[:-30]),
    "table_extra_row": folder(points=POINTS + POINTS.splitlines(True)[-1]),
    "table_header": folder(points=POINTS.replace("point,", "points,", 1)),
    "table_fraction": folder(points=POINTS.replace(",0.5,0,0.5,", ",1.5,0,0.5,")),
    "table_number": folder(points=POINTS.replace("0.0889,", "0x1p3,")),
    # a row with a NUL byte behind a valid check was taken, and read as a string cut short
    "regress-nul-row": folder(a=ROWS_A + row(1) + ",0.0\x003,00000000\n", flags=1),
    # a count of 100 digits behind a valid check: merged into a map.csv map-plot refused
    "regress-count-digits": folder(a=ROWS_A.replace(",1000,0,1,", ",1000," + "2" * 103 + ",1,", 1), flags=1),
    "no_table": bytes([0]) + "@@\n".join([IDENTITY, ROWS_A, ROWS_B]).encode("latin-1"),
}
for name, data in maps.items():
    write("fuzz_map", name, data)

# ---- fuzz_scene_set --------------------------------------------------------------
# The scene, a line "#@set", then assignments each ended by a NUL byte.
# fig6 with 2 modes: its modal analysis and shape fit (scene_build) cost less
# than half of the 5 modes', and the build is most of an execution's time
FIG6 = "[scene]\nbase = fig6.ini\n[numerics]\nmodes = 2\n"


def with_sets(scene, *sets):
    return scene + "\n#@set\n" + "".join(s + "\0" for s in sets)


scene_sets = {
    "fig6_short": with_sets(FIG6, "run.t_end=0.001", "excitation.frequency=110"),
    "fig6_5_modes": with_sets("[scene]\nbase = fig6.ini\n", "run.t_end=0.001"),
    "pcs": with_sets(FIG6, "run.model=pcs", "run.s0=0.5"),
    "resistor": with_sets(FIG6, "transducer.load=resistor", "transducer.resistance=1e5"),
    "rectifier": with_sets(FIG6, "transducer.load=rectifier", "transducer.diode_drop=0.2"),
    "implicit": with_sets(FIG6, "numerics.integrator=implicit", "numerics.theta=0.75", "numerics.dt=1e-4"),
    "modes_1": with_sets(FIG6, "numerics.modes=1"),
    "twice": with_sets(FIG6, "excitation.frequency=110", "excitation.frequency=120"),
    "newline": with_sets(FIG6, "scene.name=a\nb"),
    "escape": with_sets(FIG6, "scene.description=x\x1b[2Jy"),
    "tab": with_sets(FIG6, "scene.name=a\tb"),
    "comment_end": with_sets(FIG6, "scene.name=x */ int injected = 42; /*"),
    "unknown": with_sets(FIG6, "beam.colour=red", "bogus.key=1"),
    "no_dot": with_sets(FIG6, "frequency=110"),
    "no_equals": with_sets(FIG6, "excitation.frequency"),
    "empty_value": with_sets(FIG6, "excitation.frequency="),
    "dot_first": with_sets(FIG6, ".frequency=1", "excitation.=1"),
    "long_names": with_sets(FIG6, "s" * 40 + "." + "k" * 40 + "=1"),
    "long_value": with_sets(FIG6, "scene.description=" + "d" * 300),
    "tiny_capacitance": with_sets(FIG6, "transducer.load=resistor", "transducer.capacitance=4.9e-324"),
    "dt_tiny": with_sets(FIG6, "numerics.dt=1e-300"),
    "s0_clamp": with_sets(FIG6, "run.s0=0.99"),
    "nan": with_sets(FIG6, "excitation.acceleration=nan"),
    "not_utf8": with_sets(FIG6, "scene.name=caf\xe9"),
    "base_by_set": with_sets(FIG6, "scene.base=mssp2023.ini"),
    "bad_scene": with_sets("[beam]\nlength = x\n", "run.t_end=1"),
    "schedule": with_sets(FIG6, "excitation.schedule=0:100:10,1:120:12"),
}
for name, text in scene_sets.items():
    write("fuzz_scene_set", name, text)

# ---- fuzz_api --------------------------------------------------------------------
# head: base (% 3: fig6, fig6 + resistor, fig6 + rectifier), PCS when bits 2-4
# are all set, the other sim's base (bit 5) and model (bit 7); s0 (a value);
# then op % 10: 0 steps ((op >> 4) + 1), 1 measured step, 2 excitation, 3 state,
# 4-5 restore, 6 observer init, 7-8 observer steps, 9 predict (or, with bit 7,
# the observer on another sim). A value is (how, which[, raw]): how 1 =
# special_values[which], 2 = current * factors[which], 5 = small integer, 6 = keep.
STEPS16 = [0xF0]
INIT = [6, 0, 0]                       # defaults, gains as designed
INIT_QUICK = [6, 6, 0]                 # options given (bit 2), quick corrections (bit 1)


def obs_steps(n, accel=KEEP, measurement=KEEP):
    return [7, n - 1] + (accel + measurement) * n


def restore(*edits, flags=0):
    return [4, flags | (len(edits) - 1)] + [b for e in edits for b in e]


# kind 5: a real of the state, its index byte % 70 (BS_MAX_MODES 20, friction):
# 0 x_pcs, 1-2 frequency and amplitude, 3 step amplitude, 4 base acceleration,
# 5 q, 25 u, 45 slider pose, 48 its velocity, 51 x_C remainder, 52 percussions,
# 64 residual, 65-69 transducer (voltage, storage voltage, power, energy, its remainder)
R_STATE = 5
api = {
    "steps": [0] + KEEP + STEPS16 * 4,
    "resistor_steps": [1] + KEEP + STEPS16 * 4,
    "rectifier_steps": [2] + KEEP + STEPS16 * 4,
    "pcs": [0x1c] + KEEP + STEPS16 * 2 + restore([R_STATE, 0] + KEEP) + STEPS16,
    "measured": [0] + KEEP + [1] + KEEP + [1] + special(13) + [1] + special(0) + STEPS16,
    "excitation": [0] + KEEP + [2] + factor(4) + KEEP + STEPS16 + [2] + special(13) + KEEP,
    "state": [0] + KEEP + [3, 1, 2, 0] + factor(2) + [3, 0, 0, 0] + special(2) + STEPS16,
    "observer": [0] + KEEP + STEPS16 * 2 + INIT + obs_steps(16) * 4,
    "observer_voltage": [1] + KEEP + STEPS16 * 2 + INIT + obs_steps(16) * 4,
    "observer_quick": [0] + KEEP + INIT_QUICK + [0] + obs_steps(16, measurement=factor(4)) * 6,
    "observer_outlier": [0] + KEEP + INIT + obs_steps(8) + obs_steps(2, measurement=special(13)) + obs_steps(8),
    "observer_nan": [0] + KEEP + INIT + obs_steps(2, measurement=special(0)) + obs_steps(2, accel=special(2)),
    "observer_predict": [0] + KEEP + INIT + [9, 7] + KEEP * 8 + obs_steps(4),
    "observer_other_sim": [0] + KEEP + INIT + [139] + KEEP + [0] + [139] + KEEP + [1],
    "observer_gains_edited": [0] + KEEP + [6, 0, 3, 0, 0, 0, 5, 1, 2, 0, 5, 1, 12, 3, 5, 1, 9, 3, 5, 2] + obs_steps(4),
    "observer_latency": [0] + KEEP + [6, 0, 1, 2, 0, 0, 5, 8] + obs_steps(16) * 2,
    "observer_pcs": [0x1c] + KEEP + INIT + obs_steps(2),
    "restore_roundtrip": [0] + KEEP + STEPS16 + restore([R_STATE, 0] + KEEP) + STEPS16,
    "restore_unsealed": [0] + KEEP + STEPS16 + restore([4, 0, 7] + special(0), flags=0xe0) + STEPS16,
    "restore_magic": [0] + KEEP + restore([0, 0, 1, 0]),
    "restore_version": [0] + KEEP + restore([0, 3, 2, 1]),
    "restore_size_word": [0] + KEEP + restore([0, 5, 2, 8]),
    "restore_short": [0] + KEEP + restore([R_STATE, 0] + KEEP, flags=0x18) + [2],
    "restore_other_scene": [0x20] + KEEP + restore([R_STATE, 0] + KEEP, flags=0x1c),
    "restore_model": [0] + KEEP + restore([1, 0, 1, 1]),
    "restore_step_max": [0] + KEEP + restore([2, 0, 1, 2]),
    "restore_phase_step": [0] + KEEP + restore([2, 2, 1, 4]),
    "restore_report": [0] + KEEP + STEPS16 + restore([1, 3, 1, 10]),
    "restore_percussion": [0] + KEEP + STEPS16 + restore([R_STATE, 52] + special(6)),
    "restore_q_nan": [0] + KEEP + restore([R_STATE, 5] + special(0)),
    "restore_unused_mode": [0] + KEEP + restore([R_STATE, 24] + special(6)),
    "restore_slider": [0] + KEEP + restore([R_STATE, 45] + factor(8)),
    "restore_x_c_low": [0] + KEEP + restore([R_STATE, 51] + special(6)),
    "restore_x_pcs": [0] + KEEP + restore([R_STATE, 0] + special(7)),
    "restore_base_accel": [0] + KEEP + restore([R_STATE, 4] + special(2)),
    "restore_frequency": [0] + KEEP + restore([R_STATE, 1] + factor(2)),
    "restore_step_accel": [0] + KEEP + restore([R_STATE, 3] + factor(2)),
    "restore_transducer": [2] + KEEP + STEPS16 + restore([R_STATE, 67] + special(7)),
    "restore_cache": [0] + KEEP + STEPS16 + restore([4, 0, 120] + special(2)) + STEPS16,
}
for name, data in api.items():
    write("fuzz_api", name, bytes(data))
