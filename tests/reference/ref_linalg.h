/* ref_linalg.h - small dense linear algebra in long double for the reference
 * model: Gaussian elimination, 4x4 determinant and null vector. */
#ifndef REF_LINALG_H
#define REF_LINALG_H

/* Solves A x = b for n x n A (row-major, stride n; overwritten), b is
 * overwritten with x. Partial pivoting. Returns 0, or -1 if a pivot is
 * below rel_pivot * max|A| (numerically singular). n <= 16. */
int ref_linalg_solve(int n, long double *a, long double *b, long double rel_pivot);

/* det M of a 4x4 matrix (partial pivoting; M not changed). */
long double ref_linalg_det4(const long double m[4][4]);

/* A null vector v (M v ~ 0) of a 4x4 matrix of rank 3: the cofactors of the
 * row whose cofactor vector is largest; v is scaled to max|v_j| = 1. */
void ref_linalg_null4(const long double m[4][4], long double v[4]);

#endif
