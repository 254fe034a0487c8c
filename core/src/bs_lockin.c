/* bs_lockin.c - the observer's lock-in: the first-harmonic response H of a
 * signal y to the excitation a, both sampled every dt (docs/twin.md,
 * "Observer" 3; core/src/bs_observer.c step 4).
 *
 * Symbols -> variables. <x>: x through two cascaded first-order low-passes
 * of time constant tau, alpha = dt / tau (bs_lowpass2); a the aligned base
 * acceleration (bs_lockin_reference_step), y a signal.
 *
 *   b      <- (1 - alpha) b + dt a   quadrature: the leaky integral of a
 *   b~     =  b - <b>                without its offset
 *   c      =  <a b~> / <a^2>         projection: the part of b~ in phase with a
 *   b_perp =  b~ - c a               orthogonal to a: <a b_perp> = 0
 *   <b_perp^2> = <b~^2> - c <a b~>
 *   kappa  =  sqrt(<a^2> / <b_perp^2>) ~ Omega
 *   H      =  (<y a> - j kappa (<y b~> - c <y a>)) / <a^2>
 *
 * Per sample the products a^2, b~^2, a b~ (and y a, y b~ of each signal)
 * are low-passed; c, kappa and H are formed from the means when an estimate
 * is wanted. The filters are linear, so <y b~> - c <y a> is <y b_perp>
 * while c holds over their memory, as it does for a steady excitation:
 * b_perp is never formed, and H is the least-squares fit of y by a and b~
 * with the low-pass's weights. The in-phase part <y a> / <a^2> of y and the
 * quadrature part kappa <y b_perp> / <a^2> are then exact to the filters'
 * ripple (the products' 2 Omega through two stages: (2 Omega tau)^-2, 4e-5
 * at 124 Hz with tau = 0.1 s).
 *
 * Why b_perp (0.8.0). b~ lags a by less than 90 degrees: by 90 degrees -
 * atan(1/(Omega tau)) for the leak, and Omega dt / 2 less for the
 * rectangle rule (c Omega = 0.0206 at 124 Hz, tau = 0.1 s, dt = 2e-5 s).
 * Before, H was formed with b~ as the quadrature, kappa^2 = <a^2> /
 * <b~^2>: |H| came out off by -(c Omega / 2) sin 2 phi, +0.90 % at the
 * high branch's phi ~ 150 degrees, its phase by -0.87 degrees there, while
 * the response maps are exact DFTs (host/lib/observer_design.c): +0.0016
 * in s at s = 0.33 on fig6 (docs/twin.md, "Observer" 3).
 *
 * The frequency. For a = cos(Omega t), in continuous time, b~ / a =
 * (1 / (1/tau + j Omega)) (1 - 1 / (1 + j Omega tau)^2) = -j / Omega +
 * 1 / (Omega^2 tau) + O(Omega^-1 (Omega tau)^-3): the offset's removal
 * scales b~ by 1 + (Omega tau)^-2 where the leak shrinks it by as much, so
 * the quadrature part alone gives kappa = Omega (1 + O((Omega tau)^-4)),
 * and the rectangle rule adds (Omega dt)^2 / 12: 2e-5 at 124 Hz in all.
 * (Before, sqrt(<a^2> / <b~^2> - 1/tau^2) read 3e-4 low.)
 *
 * Cost per sample: the reference (the integral, <b>, and three products
 * low-passed) and two low-passes per signal; no division (alpha and
 * 1 - alpha are kept). Per estimate: two divisions and a square root for
 * the basis, none per response.
 */
#include "bs_lockin.h"
#include "bs_port.h"

void bs_lockin_reference_init(bs_lockin_reference *r, bs_real dt, bs_real tau)
{
    bs_lowpass2 *const filters[] = { &r->mean_b, &r->aa, &r->bb, &r->ab };
    int i;
    r->dt = dt;
    r->alpha = dt / tau;
    r->retain = BS_R(1.0) - r->alpha;
    r->quadrature = BS_R(0.0);
    for (i = 0; i < (int)(sizeof filters / sizeof filters[0]); ++i)
        filters[i]->stage[0] = filters[i]->stage[1] = BS_R(0.0);
}

static int finite(bs_real x)
{
    return x - x == BS_R(0.0);
}

int bs_lockin_basis_of(const bs_lockin_reference *r, bs_lockin_basis *basis)
{
    const bs_real aa = bs_lowpass2_mean(&r->aa), bb = bs_lowpass2_mean(&r->bb), ab = bs_lowpass2_mean(&r->ab);
    bs_real in_phase, c, bb_perp, kappa;
    basis->aa = basis->projection = basis->kappa = basis->in_phase = basis->quadrature = BS_R(0.0);
    if (!(aa > BS_R(0.0)))
        return 0;
    in_phase = BS_R(1.0) / aa;
    c = ab * in_phase;
    bb_perp = bb - c * ab;
    /* b~ parallel to a to rounding (a constant, or the first samples):
     * there is no quadrature */
    if (!(bb_perp > BS_REAL_EPS * bb))
        return 0;
    kappa = bs_sqrt(aa / bb_perp);
    if (!finite(kappa) || !finite(in_phase) || !finite(c))
        return 0;
    basis->aa = aa;
    basis->projection = c;
    basis->kappa = kappa;
    basis->in_phase = in_phase;
    basis->quadrature = kappa * in_phase;
    return 1;
}

void bs_lockin_response_of(const bs_lockin_basis *basis, bs_real ya, bs_real yb, bs_real *re, bs_real *im)
{
    *re = basis->in_phase * ya;
    *im = -basis->quadrature * (yb - basis->projection * ya);
}

void bs_lockin_response(const bs_lockin_basis *basis, const bs_lowpass2 *with_a, const bs_lowpass2 *with_b,
                        bs_real *re, bs_real *im)
{
    bs_lockin_response_of(basis, bs_lowpass2_mean(with_a), bs_lowpass2_mean(with_b), re, im);
}
