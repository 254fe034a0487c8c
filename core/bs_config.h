/* bs_config.h - compile-time sizes of the core.
 *
 * Every array in the core is sized here, so a bs_sim has a size known at
 * compile time and the caller can place it statically. The host build uses
 * generous limits and a run-time mode count; an embedded build compiled
 * against one scene overrides them (see configs/).
 */
#ifndef BS_CONFIG_H
#define BS_CONFIG_H

/* Largest number of beam modes a scene may use. */
#ifndef BS_MAX_MODES
#define BS_MAX_MODES 20
#endif

/* Mode shapes are piecewise polynomials of this many coefficients (degree 7),
 * fitted on the host; see core/bs_shape.h (whose Horner loop is written out
 * for exactly 8). */
#define BS_SHAPE_COEFS 8

/* Largest number of polynomial pieces over the beam length. */
#ifndef BS_SHAPE_MAX_PIECES
#define BS_SHAPE_MAX_PIECES 128
#endif

/* Degrees of freedom: N modal coordinates, then x_C, z_C, beta. */
#define BS_MAX_DOF (BS_MAX_MODES + 3)

/* Contacts: the four slot corners P1..P4, then the left and right clamp end
 * stops (normal-only contacts acting on x_C). */
#define BS_CORNERS 4
#define BS_MAX_CONTACTS 6
#define BS_STOP_LEFT 4
#define BS_STOP_RIGHT 5

#endif
