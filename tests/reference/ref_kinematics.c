/* ref_kinematics.c - gaps and force directions (docs/model.md 4) in the base
 * frame (docs/model.md 10: z_r = z_C - w0, so w0 leaves r_B and w~ = 0).
 *
 *   A(beta) = [[cos b, sin b], [-sin b, cos b]],  A'(beta) = [[0, 1], [-1, 0]] A(beta)
 *   r_P = (x_C, z_r) + A r_CP          (PCS: x_C := s~ L here)
 *   w, w' = dw/dx at x_P; alpha = atan w'; beyond [0, L] the beam is rigid: w = w' = 0
 *   r_B = (x_P, w) + zeta h/2 (-w', 1)
 *   n = zeta (-sin a, cos a), t = zeta (-cos a, -sin a), C = [n^T; t^T]
 *   g = C (r_P - r_B)
 *   W^T, slider part:  C [I_2 | A' r_CP]
 *   W^T, beam part:    -C dr_B/dq_b + C' (r_P - r_B) phi'^T,  C' = dC/dalpha = [t^T; -n^T]
 *       dr_B/dq_k = (0, phi_k) + zeta h/2 [(-phi_k', 0) - (-w'^2, w') phi_k']
 *       (the published model: d alpha/dq ~ phi', the x_P dependence through
 *       x_C and beta neglected)
 *   w~ = 0 (was -C (0, dw0) in the inertial frame of docs/model.md 4)
 *   End stops (frictionless, restitution e_N): g = x_C - x_left (left),
 *   g = x_right - x_C (right), x_left = B/2 or x_2 + B/2 beside a patch at the
 *   left clamp, x_right = L - B/2 or x_1 - B/2 (docs/model.md 11); W = +-e_xC. */
#include "ref_kinematics.h"

#include <math.h>

double ref_kinematics_x(const ref_scene *scene, const double *q)
{
    return scene->model == REF_MODEL_PCS ? scene->s_pcs * scene->length : q[scene->i_x];
}

void ref_kinematics_corner(const ref_scene *scene, const double *q, int i, ref_contact *c)
{
    const double beta = q[scene->i_beta];
    const double cb = cos(beta), sb = sin(beta);
    const double rx = scene->corner[i][0], rz = scene->corner[i][1];
    const double zeta = scene->zeta[i];
    const double hh = scene->half_thickness;
    const double arot[2] = { cb * rx + sb * rz, -sb * rx + cb * rz };  /* A r_CP */
    const double darot[2] = { -sb * rx + cb * rz, -cb * rx - sb * rz }; /* A' r_CP */
    double r_p[2], r_b[2], d[2], n[2], t[2];
    double phi[REF_MAX_MODES], phi_x[REF_MAX_MODES];
    double w, w_x, alpha, sa, ca, t_d, n_d;
    int k;

    r_p[0] = ref_kinematics_x(scene, q) + arot[0];
    r_p[1] = q[scene->i_z] + arot[1];
    ref_scene_beam(scene, q, r_p[0], &w, &w_x, phi, phi_x);
    alpha = atan(w_x);
    sa = sin(alpha);
    ca = cos(alpha);
    r_b[0] = r_p[0] - zeta * hh * w_x;
    r_b[1] = w + zeta * hh;
    n[0] = -zeta * sa;
    n[1] = zeta * ca;
    t[0] = -zeta * ca;
    t[1] = -zeta * sa;
    d[0] = r_p[0] - r_b[0];
    d[1] = r_p[1] - r_b[1];
    n_d = n[0] * d[0] + n[1] * d[1];
    t_d = t[0] * d[0] + t[1] * d[1];

    c->id = i;
    c->dim = 2;
    c->gap[0] = n_d;
    c->gap[1] = t_d;
    c->mu = scene->mu;
    c->e_n = scene->e_n;
    for (k = 0; k < scene->n_q; ++k)
        c->dir[0][k] = c->dir[1][k] = 0.0;
    for (k = 0; k < scene->n_modes; ++k) {
        const double drb_x = zeta * hh * (-phi_x[k] + w_x * w_x * phi_x[k]);
        const double drb_z = phi[k] - zeta * hh * w_x * phi_x[k];
        c->dir[0][k] = -(n[0] * drb_x + n[1] * drb_z) + t_d * phi_x[k];
        c->dir[1][k] = -(t[0] * drb_x + t[1] * drb_z) - n_d * phi_x[k];
    }
    c->dir[0][scene->i_x] = n[0];
    c->dir[0][scene->i_z] = n[1];
    c->dir[0][scene->i_beta] = n[0] * darot[0] + n[1] * darot[1];
    c->dir[1][scene->i_x] = t[0];
    c->dir[1][scene->i_z] = t[1];
    c->dir[1][scene->i_beta] = t[0] * darot[0] + t[1] * darot[1];
}

void ref_kinematics_stop(const ref_scene *scene, const double *q, int id, ref_contact *c)
{
    const double sign = id == REF_STOP_LEFT ? 1.0 : -1.0;
    int k;

    c->id = id;
    c->dim = 1;
    c->gap[0] = id == REF_STOP_LEFT ? q[scene->i_x] - scene->stop_left : scene->stop_right - q[scene->i_x];
    c->gap[1] = 0.0;
    for (k = 0; k < scene->n_q; ++k)
        c->dir[0][k] = c->dir[1][k] = 0.0;
    c->dir[0][scene->i_x] = sign;
    c->mu = 0.0;
    c->e_n = scene->e_n;
}

int ref_kinematics_closed(const ref_scene *scene, const double *q_m, ref_contact out[REF_MAX_CONTACTS])
{
    int count = 0, i;

    for (i = 0; i < REF_CORNERS; ++i) {
        ref_kinematics_corner(scene, q_m, i, &out[count]);
        if (out[count].gap[0] < 0.0)
            ++count;
    }
    if (scene->end_stops)
        for (i = REF_STOP_LEFT; i <= REF_STOP_RIGHT; ++i) {
            ref_kinematics_stop(scene, q_m, i, &out[count]);
            if (out[count].gap[0] < 0.0)
                ++count;
        }
    return count;
}
