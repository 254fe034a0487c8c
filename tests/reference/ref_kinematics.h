/* ref_kinematics.h - contact gaps and force directions W_i of the reference
 * model (docs/model.md 4) in the base frame of docs/model.md 10 (no w0 in the
 * gap, w~_i = 0), and the clamps' end stops (docs/model.md 9.6, 11). */
#ifndef REF_KINEMATICS_H
#define REF_KINEMATICS_H

#include "ref_scene.h"

#define REF_STOP_LEFT REF_CORNERS        /* contact id of the stop at x_C = B/2 (x_2 + B/2 beside a patch) */
#define REF_STOP_RIGHT (REF_CORNERS + 1) /* contact id of the stop at x_C = L - B/2 (x_1 - B/2) */

/* One contact: corner P1..P4 (id 0..3; normal and tangential row) or end stop
 * (id 4, 5; normal row only, frictionless). In the base frame the gap does
 * not depend on time, so there is no w~ (docs/model.md 10). */
typedef struct ref_contact {
    int id;
    int dim;                          /* rows: 2 corner, 1 end stop */
    double gap[2];                    /* g_N, g_T [m] */
    double dir[2][REF_MAX_Q];         /* W_i columns: d g_N / d q, d g_T / d q */
    double mu;                        /* Coulomb coefficient (0 for stops) */
    double e_n;                       /* normal restitution */
} ref_contact;

/* Corner i (0..3) at state q: gap, W_i (the published model's directions,
 * docs/model.md 4); the gap does not depend on time (w~_i = 0). */
void ref_kinematics_corner(const ref_scene *scene, const double *q, int i, ref_contact *c);

/* End stop id (REF_STOP_LEFT / REF_STOP_RIGHT) at q. */
void ref_kinematics_stop(const ref_scene *scene, const double *q, int id, ref_contact *c);

/* The contacts that take part in a step at the midpoint state q_M: every
 * corner and end stop with g_N < 0 (no pre-filter). Returns their count. */
int ref_kinematics_closed(const ref_scene *scene, const double *q_m, ref_contact out[REF_MAX_CONTACTS]);

/* x_C used by the contact kinematics: the state's (free) or s~ L (PCS). */
double ref_kinematics_x(const ref_scene *scene, const double *q);

#endif
