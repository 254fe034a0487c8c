# twin_signals.awk - a plant's trajectory as a harvester measures it: the
# measured-signals file of docs/twin.md. Input: lines "t w s p" every twin
# step dt (t = k dt from k = 0; w = w(4L/7), s the plant's slider position).
# Variables: seed, stats ("RMS largest" of w), dt, and the excitation: f0, a0
# (harmonic) or schedule ("t:f:a, ..." as [excitation] schedule).
#
# Per row k >= 1: base_accel = the mean base acceleration over (t - dt, t]
# (harmonic: exactly -a (sin Omega t - sin Omega (t - dt)) / (Omega dt); a
# schedule: -a(t_M) cos(2 pi cycles(t_M)) sinc(pi f(t_M) dt), its
# midpoint rule), and w at t; each with white Gaussian noise 40 dB below its
# RMS (a / sqrt 2 for the acceleration) and quantised to 12 bits over +-2x
# its largest value (the noise-free signal's).
function gauss() { # Box-Muller
    if (have_spare) { have_spare = 0; return spare }
    do u = rand(); while (u <= 0)
    v = rand()
    r = sqrt(-2 * log(u)); spare = r * sin(2 * PI * v); have_spare = 1
    return r * cos(2 * PI * v)
}
function quantise(x, range) { # 12 bits over [-range, range]
    step = 2 * range / 4096
    return step * int(x / step + (x >= 0 ? 0.5 : -0.5))
}
function cycles(t,   k, s) { # periods of the schedule's excitation by t
    if (t <= st[1]) return sf[1] * t
    for (k = 1; k < npts && t >= st[k + 1]; ++k) ;
    if (k == npts) return sc[k] + sf[k] * (t - st[k])
    s = t - st[k]
    return sc[k] + sf[k] * s + 0.5 * (sf[k + 1] - sf[k]) / (st[k + 1] - st[k]) * s * s
}
function at(t, v,   k) { # v (sf or sa) linear between points, held outside
    if (t <= st[1]) return v == "f" ? sf[1] : sa[1]
    for (k = 1; k < npts && t >= st[k + 1]; ++k) ;
    if (k == npts) return v == "f" ? sf[k] : sa[k]
    return v == "f" ? sf[k] + (sf[k + 1] - sf[k]) * (t - st[k]) / (st[k + 1] - st[k]) \
                    : sa[k] + (sa[k + 1] - sa[k]) * (t - st[k]) / (st[k + 1] - st[k])
}
function accel(t,   tm, f, x) {
    if (npts == 0)
        return -a0 * (sin(W * t) - sin(W * (t - dt))) / (W * dt)
    tm = t - dt / 2
    f = at(tm, "f")
    x = PI * f * dt
    c = cycles(tm)
    return -at(tm, "a") * cos(2 * PI * (c - int(c))) * sin(x) / x
}
BEGIN {
    PI = atan2(0, -1)
    srand(seed)
    split(stats, st2, " "); w_rms = st2[1]; w_max = st2[2]
    npts = 0
    if (schedule != "") {
        n = split(schedule, pts, ",")
        for (i = 1; i <= n; ++i) {
            split(pts[i], tfa, ":"); ++npts
            st[npts] = tfa[1] + 0; sf[npts] = tfa[2] + 0; sa[npts] = tfa[3] + 0
        }
        sc[1] = sf[1] * st[1]
        for (k = 2; k <= npts; ++k) sc[k] = sc[k - 1] + 0.5 * (st[k] - st[k - 1]) * (sf[k - 1] + sf[k])
        a_ref = sa[1]; a_max = 0
        for (k = 1; k <= npts; ++k) if (sa[k] > a_max) a_max = sa[k]
    } else {
        W = 2 * PI * f0; a_ref = a0; a_max = a0
    }
    w_noise = 0.01 * w_rms
    a_noise = 0.01 * a_ref / sqrt(2)
    print "# beamslider measured signals (docs/twin.md, \"Observer\")"
    print "# plant = the independent reference (tests/reference), dt 5e-6 s; host/reports/twin_report.sh"
    printf "# sample_rate = %.12g Hz\n", 1 / dt
    print "# signal = deflection"
    print "# signal_unit = m"
    print "# base_accel_unit = m/s^2"
    print "# latency = 0 s"
    printf "# noise = %.9g m\n", w_noise
    printf "# accel_noise = %.9g m/s^2\n", a_noise
    print "t,base_accel,signal,s_true"
}
$1 > 0 {
    a = quantise(accel($1) + a_noise * gauss(), 2 * a_max)
    y = quantise($2 + w_noise * gauss(), 2 * w_max)
    printf "%.9g,%.9g,%.9g,%.9g\n", $1, a, y, $3
}
