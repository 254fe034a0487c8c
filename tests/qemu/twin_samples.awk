# twin_samples.awk - the per-sample costs of a twin firmware cost image (port/cortex-m/twin
# built with TWIN_COST=1), from tests/qemu/count.sh's output, summed into "NAME VALUE" lines.
# Shared by tests/qemu/twin_probe.sh and host/reports/twin_firmware_report.sh.
#
# The marks come four to a sample: the producer's bracket, then the observer step's; the first
# interval is the start-up. A sample's cost is everything from one observer step's end to the
# next, plus `entry` cycles of SysTick entry and return (with the cycle estimate), plus `extra`
# cycles on every `every`-th sample (work the image did not run; 0 by default). The backlog at
# each clock f of `clocks` [MHz]: the Lindley recursion W = max(0, W + c_k - B), B = f x dt,
# its largest W as ceil(W / B) samples; `overflow` the first sample where W passes `fifo`
# samples at the first clock.
#
# Variables: cycles (1: count.sh ran with CM_CYCLES=1; else instructions stand in for cycles
# and the clock is `mhz`), clocks, dt [s], entry, fifo, mhz, extra, every, digits (decimals of
# the step's and the sample's means; 0 by default), logfile (where the guest's other lines go;
# none by default).
function lindley(j, cost) {
    w[j] += cost - budget[j]; if (w[j] < 0) w[j] = 0
    if (w[j] > most[j]) most[j] = w[j]
}
function mean(sum, count) { return sprintf("%." (digits + 0) "f", sum / count) }
BEGIN {
    n_clock = split(clocks, clock, " ")
    if (!cycles) { n_clock = 1; clock[1] = mhz }
    for (j = 1; j <= n_clock; ++j) budget[j] = clock[j] * dt * 1e6
    if (every == "") every = 1
}
/^\[insn\] total/ { next }
/^\[insn\] [0-9]+/ { # [insn] N, or [insn] N cycles C taken T flash F
    ++marks
    if (NF >= 8) { opt = $4 + $6; pess = $4 + 3 * $6 + 5 * $8 } else { opt = pess = $2 }
    if (marks > 1) { acc_insn += $2; acc += pess }
    if (marks % 4 == 2) { ++np; p_insn += $2; p_pess += pess }
    if (marks % 4 == 0) {
        ++n; s_insn += $2; s_opt += opt; s_pess += pess
        if ($2 > s_worst_insn) s_worst_insn = $2
        if (opt > s_worst_opt) s_worst_opt = opt
        if (pess > s_worst_pess) s_worst_pess = pess
        cost = acc + (cycles ? entry : 0) + (n % every == 0 ? extra : 0)
        sample += cost; sample_insn += acc_insn
        if (cost > sample_worst) sample_worst = cost
        if (cost > budget[1]) ++over
        for (j = 1; j <= n_clock; ++j) lindley(j, cost)
        if (!overflow && w[1] > fifo * budget[1]) overflow = n
        acc = 0; acc_insn = 0
    }
    next
}
/^end status/ { for (i = 2; i < NF; ++i) end[$i] = $(i + 1) }
logfile != "" { print > logfile }
END {
    if (!n) exit 1
    printf "samples %d\nstep_insn %.0f\nstep_worst_insn %d\nproducer_insn %.1f\n", n, s_insn / n, s_worst_insn, p_insn / np
    if (cycles)
        printf "step_opt %s\nstep_worst_opt %d\nstep_pess %s\nstep_worst_pess %d\nproducer_pess %.1f\n",
            mean(s_opt, n), s_worst_opt, mean(s_pess, n), s_worst_pess, p_pess / np
    printf "sample_insn %.0f\nsample %s\nsample_worst %d\nover %d\noverflow %d\n", sample_insn / n, mean(sample, n), sample_worst, over, overflow
    for (j = 1; j <= n_clock; ++j) {
        q = int(most[j] / budget[j]); if (q * budget[j] < most[j]) ++q
        time = most[j] / budget[j] * dt
        printf "backlog_%d %d\nbacklog_time_%d %s\n", clock[j], q, clock[j], time < 1 ? sprintf("%.1f ms", time * 1e3) : sprintf("%.1f s", time)
    }
    printf "status %s\nstack %s\ns %s\nhash %s\nest %s\n", end["status"], end["stack"], end["s"], end["hash"], end["est"]
}
