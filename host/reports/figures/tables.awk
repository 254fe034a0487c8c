# tables.awk - the markdown of docs/validation.md section 7 from the numbers
# of branches.awk (prefixes fig6_b_, fig6_1mode_b_) and scenario.awk (prefix:
# the scene), read as the lines KEY='VALUE' of figures.sh's numbers.sh.
#
#   awk -v part=table|scenarios -f tables.awk numbers.sh
#
# The criteria are the ones section 7 defines; a difference is printed in
# bold as **no**, never hidden.
function v(key) {
    if (!(key in V)) { print "tables.awk: no number " key > "/dev/stderr"; failed = 1; exit 1 }
    return V[key]
}
function n(key) { return v(key) + 0 }  # awk compares strings as strings
function yn(ok) { return ok ? "yes" : "**no**" }
function abs(x) { return x < 0 ? -x : x }
function f3(x) { return sprintf("%.3f", x) }
function description(scene,    line, file) {
    file = "configs/" scene ".ini"
    while ((getline line < file) > 0)
        if (line ~ /^description *=/) { sub(/^description *= */, "", line); close(file); return line }
    close(file)
    return "?"
}
# Branch table: the column of scene (prefix p = SCENE_b_) and its verdicts (A[...]).
function branch_column(scene,    p, za, zb, cnt, parts) {
    p = scene "_b_"
    C[scene, "turn"] = v(p "s_min") " at t = " v(p "t_min") " s"
    C[scene, "jump"] = v(p "free_jump") == "yes" ? "t = " v(p "free_jump_t") " s, s = " v(p "free_jump_s") " (" \
        sprintf("%.4f", v(p "free_jump_s") - v(p "s_min")) " past the turning point)" : "no jump"
    A[scene, "jump"] = v(p "free_jump") == "yes" && n(p "free_jump_s") - n(p "s_min") <= 0.005
    C[scene, "down"] = v(p "down_jump") == "yes" ? "from " f3(v(p "down_jump_a")) " to " f3(v(p "down_jump_b")) \
        sprintf(" (amp_h %+.3f)", v(p "down_jump_da")) : "none (largest step " sprintf("%+.3f", v(p "down_jump_da")) ")"
    C[scene, "up"] = v(p "up_jump") == "yes" ? "from " f3(v(p "up_jump_a")) " to " f3(v(p "up_jump_b")) \
        sprintf(" (amp_h %+.3f)", v(p "up_jump_da")) \
        : "none in [0, 0.5]: the high branch reaches 0.5 (largest step " sprintf("%+.3f", v(p "up_jump_da")) \
          " from " f3(v(p "up_jump_a")) " to " f3(v(p "up_jump_b")) ")"
    # the free run should jump where the down sweep leaves the low branch
    A[scene, "down"] = v(p "down_jump") == "yes" && v(p "free_jump") == "yes" \
        && n(p "free_jump_s") >= n(p "down_jump_b") - 0.005 && n(p "free_jump_s") <= n(p "down_jump_a") + 0.005
    C[scene, "window"] = v(p "window") == "yes" ? f3(v(p "window_lo")) " to " f3(v(p "window_hi")) : "none"
    A[scene, "window"] = v(p "window") == "yes"
    C[scene, "amp"] = v(p "up_amp_1") " / " v(p "down_amp_1") "; " v(p "up_amp_2") " / " v(p "down_amp_2") "; " \
        v(p "up_amp_3") " / " v(p "down_amp_3") "; " v(p "up_amp_4") " / " v(p "down_amp_4")
    cnt = v(p "low_v_neg") + v(p "low_v_pos")
    C[scene, "low"] = "s " v(p "low_range") ": " v(p "low_v_neg") " of " cnt " points negative (toward the clamp), mean " v(p "low_v_mean") \
        (v(p "low_v_pos_at") != "" ? "; positive at " v(p "low_v_pos_at") : "")
    A[scene, "low"] = cnt > 0 && n(p "low_v_pos") == 0
    cnt = v(p "high_v_pos") + v(p "high_v_neg")
    C[scene, "high"] = "s " v(p "high_range") ": " v(p "high_v_pos") " of " cnt " points positive (toward the centre), mean " v(p "high_v_mean") \
        (v(p "high_v_neg_at") != "" ? "; negative at " v(p "high_v_neg_at") : "")
    A[scene, "high"] = cnt > 0 && n(p "high_v_neg") == 0
    if (!A[scene, "high"] && cnt > 0 && n(p "high_v_pos") > n(p "high_v_neg"))
        A[scene, "high_text"] = "mostly (" v(p "high_v_neg") " of " cnt " negative)"
    if (v(p "v_zero") == "none") {
        C[scene, "zero"] = "no sign change up to " f3(v(p "window_hi")) "; the free slider ends at s = " v(p "s_last10")
        A[scene, "zero"] = n(p "s_last10") >= n(p "window_hi") - 0.005
    } else {
        split(v(p "v_zero"), parts, "-"); za = parts[1] + 0; zb = parts[2] + 0
        C[scene, "zero"] = "v_mean turns negative between " f3(za) " and " f3(zb) "; the free slider ends at s = " v(p "s_last10")
        A[scene, "zero"] = v(p "s_last10") >= za - 0.005 && v(p "s_last10") <= zb + 0.005
    }
    C[scene, "follow"] = "before the jump " v(p "pre_low") " % of " v(p "pre") " averaged points are closer to the low branch, " \
        "after it " v(p "post_high") " % of " v(p "post") " closer to the high branch"
    A[scene, "follow"] = v(p "free_jump") == "yes" && n(p "pre_low") >= 90 && n(p "post_high") >= 90 && A[scene, "down"]
}
function both(key) {
    return "fig6: " (A["fig6", key "_text"] != "" ? A["fig6", key "_text"] : yn(A["fig6", key])) \
        "; one mode: " (A["fig6_1mode", key "_text"] != "" ? A["fig6_1mode", key "_text"] : yn(A["fig6_1mode", key]))
}
function row(quantity, paper, key, agreement) {
    printf "| %s | %s | %s | %s | %s |\n", quantity, paper, C["fig6", key], C["fig6_1mode", key], agreement
}
# One scenario row; sets OK[scene].
function scenario_row(scene, label,    path, numbers, retreat, ok) {
    path = "s " v(scene "_s0") " -> " v(scene "_s_final") " (range " v(scene "_s_min") "-" v(scene "_s_max") \
        "); amplitude: largest 1 s average " v(scene "_amp_avg_max") " h, last 10 s " v(scene "_amp_last10") " h; " \
        "rises above 0.5 h: " v(scene "_ups") ", falls below 0.25 h: " v(scene "_downs")
    if (label == "trivial") {
        retreat = n(scene "_drop_s") < n(scene "_rise_s") ? n(scene "_drop_s") : n(scene "_rise_s")
        numbers = "largest retreat of s against its way " sprintf("%.4f", retreat) " (needs < 0.005); last 10 s " \
            v(scene "_amp_last10") " h (needs > 0.5 h); falls: " v(scene "_downs") " (needs 0)"
        ok = retreat < 0.005 && n(scene "_amp_last10") > 0.5 && n(scene "_downs") == 0
    } else if (label == "signature") {
        numbers = "s falls " v(scene "_first_fall") " below s0 before the rise (needs > 0.005), rises at " \
            v(scene "_t_first_up") " s, then s walks back " v(scene "_walk_back") " (needs > 0.005); falls: " v(scene "_downs") " (needs 0)"
        ok = n(scene "_first_fall") > 0.005 && n(scene "_ups") >= 1 && n(scene "_walk_back") > 0.005 && n(scene "_downs") == 0
    } else if (label == "relaxation") {
        numbers = v(scene "_downs") " complete cycles (needs >= 2), a rise every " v(scene "_cycle_t") " s on average"
        ok = n(scene "_downs") >= 2
    } else {
        numbers = "largest 1 s average " v(scene "_amp_avg_max") " h (needs < 0.25 h), last 10 s " v(scene "_amp_last10") " h (needs < 0.05 h)"
        ok = n(scene "_amp_avg_max") < 0.25 && n(scene "_amp_last10") < 0.05
    }
    OK[scene] = ok
    printf "| %s | %s | %s | %s | %s |\n", scene, description(scene), path, numbers, yn(ok)
}
{
    key = $0; sub(/=.*/, "", key)
    value = $0; sub(/^[^=]*='/, "", value); sub(/'$/, "", value)
    V[key] = value
}
END {
    if (failed)
        exit 1
    if (part == "table") {
        branch_column("fig6"); branch_column("fig6_1mode")
        print "Sweeps: s = 0 to 0.5 in steps of 0.005, 100 excitation periods held and 25 recorded per point, each"
        print "sweep from rest. Free runs: the scene's t_end. Cells with two numbers: up sweep / down sweep."
        print ""
        print "| quantity | docs/model.md 8 / seed paper | fig6 (five modes) | fig6_1mode (one mode) | agreement |"
        print "|---|---|---|---|---|"
        row("turning point of the free run (min s)", "0.24-0.25 (fig6); ~0.24 (seed paper, one mode)", "turn",
            "fig6: " (n("fig6_b_s_min") >= 0.24 && n("fig6_b_s_min") <= 0.25 ? "yes" : \
                sprintf("**no** (%+.3f beyond 0.25)", v("fig6_b_s_min") - 0.25)) \
            "; one mode: " (abs(n("fig6_1mode_b_s_min") - 0.24) <= 0.005 ? "yes" : \
                sprintf("**no** (%+.3f from 0.24)", v("fig6_1mode_b_s_min") - 0.24)))
        row("free run: jump to the high branch (first period above 0.5 h)", "jumps up at the turning point", "jump",
            both("jump") " (within 0.005)")
        row("down sweep: jump (largest step between neighbouring points)",
            "jumps up where the attached f_1 meets 124 Hz, s ~ 0.25", "down",
            both("down") " (free run jumps inside it, +-0.005)")
        row("up sweep: jump", "not stated", "up", "-")
        row("hysteresis window (grid points where the branches differ)", "two branches with hysteresis", "window", both("window"))
        row("amp_h at s = 0.1; 0.2; 0.3; 0.4 (up / down)", "figure only, no numbers", "amp", "-")
        row("v_mean on the low branch where the free run visits it (before its jump)", "toward the clamp (seed paper)",
            "low", both("low"))
        row("v_mean on the high branch where the free run visits it (after its jump)", "toward the centre (seed paper)",
            "high", both("high"))
        row("where v_mean on the high branch turns negative vs where the free slider settles (mean s, last 10 s)",
            "not stated (consistency of the two models)", "zero", both("zero") " (within a grid step)")
        row("free trajectory: follows the low branch, jumps, follows the high branch", "yes (the papers' Fig. 1b)",
            "follow", both("follow") " (both >= 90 %, jump inside the down sweep's)")
    } else {
        print "| scene | label (docs/model.md 8) | what the free run did | deciding numbers (criterion) | matches |"
        print "|---|---|---|---|---|"
        scenario_row("fig6", "signature")
        scenario_row("fig7", "trivial")
        scenario_row("fig8", "relaxation")
        scenario_row("fig9", "damping")
        scenario_row("fig12a", "trivial")
        scenario_row("fig12b", "signature")
        print ""
        printf "Start dependence (fig12a and fig12b: the same excitation, s0 = %s and %s): ", v("fig12a_s0"), v("fig12b_s0")
        printf "trivial adaptation from %s and a signature move from %s: %s. ", v("fig12a_s0"), v("fig12b_s0"),
            yn(OK["fig12a"] && OK["fig12b"])
        printf "Final states: s = %s and %s (difference %.4f), amplitude over the last 10 s %s h and %s h.\n",
            v("fig12a_s_final"), v("fig12b_s_final"), abs(v("fig12a_s_final") - v("fig12b_s_final")),
            v("fig12a_amp_last10"), v("fig12b_amp_last10")
        ensemble_line()
    }
}
# fig8 from several starts 1e-5 apart (prefixes fig8_e0.., e0 the table's run): one
# run of a chaotic scene need not be typical, so the line says what each start did
function ensemble_line(    k, m, cycles, lo, hi, slo, shi, ok, d, same) {
    m = n("fig8_ensemble"); lo = 1e9; hi = -1; slo = 2; shi = -1; ok = 0; cycles = ""
    for (k = 0; k < m; ++k) {
        d = n("fig8_e" k "_downs")
        cycles = cycles (k ? ", " : "") d
        if (d < lo) lo = d
        if (d > hi) hi = d
        ok += d >= 2
        if (n("fig8_e" k "_s_final") < slo) slo = n("fig8_e" k "_s_final")
        if (n("fig8_e" k "_s_final") > shi) shi = n("fig8_e" k "_s_final")
    }
    printf "\nfig8 from %d starts s0 = %s + k %s (k = 0..%d; docs/figures/run_fig8_ensemble.png, k = 0 is the run above): ", \
        m, v("fig8_e0_s0"), v("fig8_ensemble_step"), m - 1
    printf "complete cycles in %s s: %s (k = 0..%d), from %d to %d; a relaxation oscillation by the criterion (>= 2 cycles) from %d of %d starts; ", \
        v("fig8_e0_t_end"), cycles, m - 1, lo, hi, ok, m
    same = 0
    for (k = 0; k < m; ++k) same += n("fig8_e" k "_downs") == n("fig8_e0_downs")
    printf "s at the end between %.4f and %.4f. The run above completes %d; %d of the %d starts complete as many.\n", \
        slo, shi, n("fig8_e0_downs"), same, m
}
