/* ref_linalg.c - small dense linear algebra in long double.
 *
 * solve:  A x = b by Gaussian elimination with row pivoting,
 *         singular when |pivot| <= rel_pivot * max_ij |A_ij|.
 * det4:   det M = product of the pivots times the sign of the row permutation.
 * null4:  for rank M = 3, adj(M) = v u^T with M v = 0, so any non-zero row of
 *         cofactors C_rj = (-1)^(r+j) det(M without row r, column j) is a null
 *         vector (sum_j M_ij C_rj = delta_ir det M = 0). */
#include "ref_linalg.h"

#include <math.h>

#define REF_LINALG_MAX 16

int ref_linalg_solve(int n, long double *a, long double *b, long double rel_pivot)
{
    long double scale = 0.0L;
    int i, j, k;

    if (n < 1 || n > REF_LINALG_MAX)
        return -1;
    for (i = 0; i < n * n; ++i)
        if (fabsl(a[i]) > scale)
            scale = fabsl(a[i]);
    if (scale == 0.0L)
        return -1;
    for (k = 0; k < n; ++k) {
        int pivot_row = k;
        for (i = k + 1; i < n; ++i)
            if (fabsl(a[i * n + k]) > fabsl(a[pivot_row * n + k]))
                pivot_row = i;
        if (!(fabsl(a[pivot_row * n + k]) > rel_pivot * scale))
            return -1;
        if (pivot_row != k) {
            long double swap;
            for (j = 0; j < n; ++j) {
                swap = a[k * n + j];
                a[k * n + j] = a[pivot_row * n + j];
                a[pivot_row * n + j] = swap;
            }
            swap = b[k];
            b[k] = b[pivot_row];
            b[pivot_row] = swap;
        }
        for (i = k + 1; i < n; ++i) {
            const long double factor = a[i * n + k] / a[k * n + k];
            if (factor == 0.0L)
                continue;
            for (j = k; j < n; ++j)
                a[i * n + j] -= factor * a[k * n + j];
            b[i] -= factor * b[k];
        }
    }
    for (i = n - 1; i >= 0; --i) {
        long double sum = b[i];
        for (j = i + 1; j < n; ++j)
            sum -= a[i * n + j] * b[j];
        b[i] = sum / a[i * n + i];
    }
    return 0;
}

long double ref_linalg_det4(const long double m[4][4])
{
    long double a[4][4];
    long double det = 1.0L;
    int i, j, k;

    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j)
            a[i][j] = m[i][j];
    for (k = 0; k < 4; ++k) {
        int pivot_row = k;
        for (i = k + 1; i < 4; ++i)
            if (fabsl(a[i][k]) > fabsl(a[pivot_row][k]))
                pivot_row = i;
        if (a[pivot_row][k] == 0.0L)
            return 0.0L;
        if (pivot_row != k) {
            for (j = 0; j < 4; ++j) {
                const long double swap = a[k][j];
                a[k][j] = a[pivot_row][j];
                a[pivot_row][j] = swap;
            }
            det = -det;
        }
        det *= a[k][k];
        for (i = k + 1; i < 4; ++i) {
            const long double factor = a[i][k] / a[k][k];
            for (j = k; j < 4; ++j)
                a[i][j] -= factor * a[k][j];
        }
    }
    return det;
}

/* det of the 3x3 matrix left when row r and column c are removed */
static long double minor3(const long double m[4][4], int r, int c)
{
    long double s[3][3];
    int i, j, si = 0;

    for (i = 0; i < 4; ++i) {
        int sj = 0;
        if (i == r)
            continue;
        for (j = 0; j < 4; ++j) {
            if (j == c)
                continue;
            s[si][sj++] = m[i][j];
        }
        ++si;
    }
    return s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1])
           - s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0])
           + s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
}

void ref_linalg_null4(const long double m[4][4], long double v[4])
{
    long double best_norm = -1.0L;
    int r, j;

    for (r = 0; r < 4; ++r) {
        long double cof[4];
        long double norm = 0.0L;
        for (j = 0; j < 4; ++j) {
            cof[j] = ((r + j) % 2 ? -1.0L : 1.0L) * minor3(m, r, j);
            if (fabsl(cof[j]) > norm)
                norm = fabsl(cof[j]);
        }
        if (norm > best_norm) {
            best_norm = norm;
            for (j = 0; j < 4; ++j)
                v[j] = cof[j];
        }
    }
    if (best_norm > 0.0L)
        for (j = 0; j < 4; ++j)
            v[j] /= best_norm;
}
