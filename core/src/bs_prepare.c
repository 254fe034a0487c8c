/* bs_prepare.c - the scene as the step reads it (bs_step_constants).
 *
 * A step reads its constants every time; read through the scene pointer they
 * cost a load each, and on a microcontroller that keeps the scene in flash a
 * load with wait states (docs/embedded.md). So bs_sim_init copies what the
 * step needs into the sim (RAM), once, in the forms the step uses:
 *   dt gamma_k, dt omega_k^2, dt 2 D omega_k     (the smooth part's products with dt)
 *   S' = sqrt(dt) S                              (E' = q^T S' q, dt N(q) = E' S' q)
 *   the stability limit in those units           (core/src/bs_beam.c)
 *   dt g, 1 + eps of the compliance, slope_scale = 2 shape_scale,
 *   the geometry and the contact laws            (mu and e_N settable at run time)
 * The stability shortcut: for a positive semidefinite S the cubic term's
 * stiffness dN/dq = 2 (Sq)(Sq)^T + E S has largest eigenvalue at most
 * 2 |Sq|^2 + E rho <= 3 rho E (|Sq|^2 <= rho q^T S q), rho >= lambda_max(S)
 * the largest absolute row sum; so with the linear part, the explicit limit
 * holds while dt omega_max^2 + 3 rho' E' < 4 / dt (primes: the sqrt(dt)
 * units above), i.e. while E' is below stretch_limit. Whether S is
 * semidefinite is decided here by an LDL^T factorisation; without it there
 * is no shortcut, and every step takes the exact bound.
 */
#include "bs_prepare.h"
#include "bs_contact.h"
#include "bs_piezo.h"
#include "bs_port.h"
#include "bs_sim_internal.h"

#if BS_WITH_STRETCHING
/* 1 if the symmetric n x n matrix s is positive semidefinite: its LDL^T
 * factorisation has no pivot below -16 eps of the diagonal's size (a
 * semidefinite matrix's zero pivots round either way), in a copy. */
static int semidefinite(const bs_real (*s)[BS_MAX_MODES], int n)
{
    bs_real a[BS_MAX_MODES][BS_MAX_MODES];
    bs_real size = BS_R(0.0);
    int i, j, k;
    for (i = 0; i < n; ++i) {
        for (j = 0; j < n; ++j)
            a[i][j] = s[i][j];
        size = bs_fabs(s[i][i]) > size ? bs_fabs(s[i][i]) : size;
    }
    for (k = 0; k < n; ++k) {
        const bs_real pivot = a[k][k];
        if (pivot < BS_R(-16.0) * BS_REAL_EPS * size)
            return 0;
        if (!(pivot > BS_R(16.0) * BS_REAL_EPS * size)) {
            /* a zero pivot: its row must vanish too, or the matrix is indefinite */
            for (j = k + 1; j < n; ++j)
                if (bs_fabs(a[k][j]) > BS_R(16.0) * BS_REAL_EPS * size)
                    return 0;
            continue;
        }
        for (i = k + 1; i < n; ++i) {
            const bs_real factor = a[i][k] / pivot;
            for (j = k + 1; j < n; ++j)
                a[i][j] -= factor * a[k][j];
        }
    }
    return 1;
}
#endif

void bs_prepare(bs_sim *sim)
{
    const bs_scene *scene = sim->scene;
    bs_step_constants *k = &sim->k;
    const int n = scene->n_modes;
    bs_real omega_sq_max = BS_R(0.0), extra = BS_R(0.0);
    int i, j;

    k->dt = scene->dt;
    k->half_dt = BS_R(0.5) * scene->dt;
    for (i = 0; i < BS_MAX_MODES; ++i) {
        const int used = i < n;
        k->dt_gamma[i] = used ? scene->dt * scene->gamma[i] : BS_R(0.0);
        k->dt_omega_sq[i] = used ? scene->dt * scene->omega_sq[i] : BS_R(0.0);
        k->dt_damping[i] = used ? scene->dt * scene->damping[i] : BS_R(0.0);
        k->phi_sensor[i] = used ? scene->phi_sensor[i] : BS_R(0.0);
#if BS_WITH_IMPLICIT
        k->mode_gain[i] = used && scene->implicit ? scene->mode_gain[i] : BS_R(1.0);
#endif
        if (used && scene->omega_sq[i] > omega_sq_max)
            omega_sq_max = scene->omega_sq[i];
    }
#if BS_WITH_PIEZO
    extra = bs_piezo_stiffness(scene);
#endif
    k->stiffness_limit = BS_R(4.0) / (scene->dt * scene->dt);
#if BS_WITH_STRETCHING
    {
        const bs_real root_dt = bs_sqrt(scene->dt);
        bs_real rho = BS_R(0.0);
        for (i = 0; i < BS_MAX_MODES; ++i) {
            k->stretch_rows[i] = BS_R(0.0);
            for (j = 0; j < BS_MAX_MODES; ++j) {
                k->stretch[i][j] = i < n && j < n ? root_dt * scene->stretch[i][j] : BS_R(0.0);
                k->stretch_rows[i] += bs_fabs(k->stretch[i][j]);
            }
            rho = k->stretch_rows[i] > rho ? k->stretch_rows[i] : rho;
        }
        /* the implicit step integrates the linear part implicitly: only the
         * cubic term counts against the limit there */
        if (BS_WITH_IMPLICIT && scene->implicit)
            omega_sq_max = BS_R(0.0);
        k->stretch_parity = 1;
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j)
                if ((i + j) % 2 && scene->stretch[i][j] != BS_R(0.0))
                    k->stretch_parity = 0;
        k->stretch_limit = BS_R(-1.0);
        if (rho > BS_R(0.0) && semidefinite((const bs_real(*)[BS_MAX_MODES])k->stretch, n))
            k->stretch_limit = (BS_R(4.0) / scene->dt - scene->dt * (omega_sq_max + extra)) / (BS_R(3.0) * rho);
    }
#endif
    (void)omega_sq_max;
    (void)extra;
    for (i = 0; i < BS_CORNERS; ++i) {
        k->corner[i][0] = scene->corner[i][0];
        k->corner[i][1] = scene->corner[i][1];
    }
    k->half_thickness = scene->half_thickness;
    k->length = scene->length;
    k->stop_min = scene->stop_min;
    k->stop_max = scene->stop_max;
    k->escape_min = scene->stop_min - scene->half_thickness;
    k->escape_max = scene->stop_max + scene->half_thickness;
    k->shape_scale = scene->shape_scale;
    k->slope_scale = BS_R(2.0) * scene->shape_scale;
    k->mass_inv = scene->mass_inv;
    k->inertia_inv = scene->inertia_inv;
    k->dt_gravity[0] = scene->dt * scene->gravity[0];
    k->dt_gravity[1] = scene->dt * scene->gravity[1];
    k->mu = scene->mu;
    k->e_n = scene->e_n;
    k->compliance[0] = BS_R(1.0) + BS_CONTACT_COMPLIANCE;
    k->compliance[1] = BS_R(1.0) + BS_CONTACT_COMPLIANCE_T;
    bs_contact_prepare(k);
    bs_excitation_prepare(k);
}
