/* bs_contact.h - contact kinematics, Delassus operator and percussions. */
#ifndef BS_CONTACT_H
#define BS_CONTACT_H

#include "bs_sim_layout.h"

/* Relative compliance added to the diagonal of G, normal and tangential rows
 * (bs_contact.c; docs/design.md 6 has the measurements behind the values). */
#define BS_CONTACT_COMPLIANCE (BS_REAL_FLOAT ? BS_R(3e-7) : BS_R(1e-8))
#define BS_CONTACT_COMPLIANCE_T (BS_REAL_FLOAT ? BS_R(3e-6) : BS_R(1e-8))

/* Configuration at which contacts are detected (the Moreau midpoint). */
typedef struct bs_contact_frame {
    const bs_real *q_beam;  /* modal coordinates */
    bs_real x_kinematic;    /* x_C used for the contact points (x_pcs in the PCS model) [m] */
    bs_real x_stops;        /* x_C checked against the clamp end stops [m] */
    bs_real z;              /* z_r = z_C - w0, the slot's height relative to the base [m] */
    bs_real beta;           /* [rad] */
    int stops;              /* 1: clamp end stops take part */
    bs_shape_cache *cache;  /* the mode shapes about the left and right corners (2; updated) */
    bs_real reach;          /* of the expansions (bs_shape_reach) */
    const bs_real (*warm)[BS_ROWS]; /* each contact's last percussion (bs_sim.percussion): the warm start */
} bs_contact_frame;

/* The contact kinematics' own constants in k (bs_prepare). */
void bs_contact_prepare(bs_step_constants *k);

/* Finds the contacts with g_N < 0 and fills set->count, id, mu (with
 * friction), phi and phi' at each corner in contact and the coefficients and
 * slider parts of its force directions W (k: the sim's prepared constants),
 * and set->percussion with their warm starts.
 * Returns BS_OK, or BS_E_ESCAPED when a slot corner is on the wrong side of
 * the beam's axis (the slider has left the beam). */
bs_status bs_contact_detect(const bs_scene *scene, const bs_step_constants *k, const bs_contact_frame *frame,
                            bs_contact_set *set);

/* The contact problem of the contacts found: set->free_velocity, c = W^T u
 * at the free velocities u (u_slider: x_C, z_r, beta velocities, in the
 * base's frame: no base term) plus on the normal row e_N times W_N^T u at the
 * velocities before the step (Newton's impact law); and set->delassus,
 * G = W^T M^-1 W with the compliance on its diagonal. One pass over the
 * modes per contact and per pair of corners. */
void bs_contact_problem(const bs_scene *scene, const bs_step_constants *k, bs_contact_set *set,
                        const bs_real *u_beam, const bs_real *u_slider, const bs_real *u_beam_before,
                        const bs_real *u_slider_before);

/* u += M^-1 W P. */
void bs_contact_apply(const bs_scene *scene, const bs_step_constants *k, const bs_contact_set *set,
                      bs_real *u_beam, bs_real *u_slider);

#endif
