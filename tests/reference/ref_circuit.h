/* ref_circuit.h - the exact update of a first-order circuit over one step
 * (docs/model.md 11): a capacitor C discharged through a resistor R while a
 * constant current i flows in, tau = R C,
 *
 *   C y' + y / R = i   ->   y(s) = y_B e^(-s/tau) + A (1 - e^(-s/tau)),  A = R i,
 *
 * for 0 <= s <= dt. Every factor below is a mean over the step of a function
 * of e = e^(-s/tau), x = dt / tau, computed without cancellation (series for
 * small x), so that no R > 0, however small or large, loses accuracy. */
#ifndef REF_CIRCUIT_H
#define REF_CIRCUIT_H

typedef struct ref_circuit_factors {
    long double decay;   /* e^(-x): y_E = decay y_B + (1 - decay) A */
    long double gain;    /* 1 - e^(-x) */
    long double mean;    /* mean of e = (1 - e^(-x)) / x */
    long double rise;    /* mean of 1 - e = 1 - mean */
    long double mean2;   /* mean of e^2 = (1 - e^(-2x)) / (2x) */
    long double cross;   /* mean of e (1 - e) = mean - mean2 */
    long double square;  /* mean of (1 - e)^2 = 1 - 2 mean + mean2 */
} ref_circuit_factors;

/* The factors for x = dt / tau >= 0 (x = 0: no decay at all). */
void ref_circuit_factors_init(long double x, ref_circuit_factors *f);

/* Mean of y over the step: mean y_B + rise A. */
long double ref_circuit_mean(const ref_circuit_factors *f, long double y_b, long double a);

/* Mean of y^2 over the step: mean2 y_B^2 + 2 cross y_B A + square A^2
 * (the energy into R is dt / R times this). */
long double ref_circuit_mean_square(const ref_circuit_factors *f, long double y_b, long double a);

#endif
