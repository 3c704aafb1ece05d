"""The C source's solvers, written as loops, and its tests of a number by its bits.

``SOLVERS`` opens every C source: the finiteness test and the NaN that
``NAME_rhs`` returns (docs/generated-code.md, "Undefined points"), then the
Cholesky solve of M u = F. ``LU_SOLVE`` is the dense solve the reactions of
a large system use.
"""

from string import Template

LU_SOLVE = Template('''
/* Solve K z = b in place (n*n, row-major) by LU with partial pivoting: b
   becomes z. Returns 0, or j + 1 when pivot j is below n*eps times the
   largest entry of K (K is singular to working precision) or not a number. */
static int ${name}_lu_solve(int n, double *K, double *b)
{
    int i, j, s;
    double tiny = 0.0;
    for (i = 0; i < n*n; ++i) {
        if (fabs(K[i]) > tiny) {
            tiny = fabs(K[i]);
        }
    }
    tiny *= n*2.220446049250313e-16;
    for (j = 0; j < n; ++j) {
        int p = j;
        double big = fabs(K[j*n + j]);
        for (i = j + 1; i < n; ++i) {
            if (fabs(K[i*n + j]) > big) {
                big = fabs(K[i*n + j]);
                p = i;
            }
        }
        if (!(big > tiny)) {
            return j + 1;
        }
        if (p != j) {
            double v;
            for (s = 0; s < n; ++s) {
                v = K[j*n + s];
                K[j*n + s] = K[p*n + s];
                K[p*n + s] = v;
            }
            v = b[j];
            b[j] = b[p];
            b[p] = v;
        }
        for (i = j + 1; i < n; ++i) {
            const double f = K[i*n + j]/K[j*n + j];
            if (f != 0.0) {
                for (s = j + 1; s < n; ++s) {
                    K[i*n + s] -= f*K[j*n + s];
                }
                b[i] -= f*b[j];
            }
        }
    }
    for (i = n - 1; i >= 0; --i) {
        double v = b[i];
        for (s = i + 1; s < n; ++s) {
            v -= K[i*n + s]*b[s];
        }
        b[i] = v/K[i*n + i];
    }
    return 0;
}
''')

# isfinite and NAN are what -ffast-math (-ffinite-math-only) lets a compiler
# fold away: gcc and clang then compile isfinite(x) to 1, and clang warns on
# NAN. An IEEE double's exponent bits say it whatever the flags; a union is
# the type pun C99 (TC3) and both compilers define, and needs no header
# beyond <math.h> (unsigned long long has at least 64 bits).
SOLVERS = Template('''
/* 1 when v is a finite number. Read from the IEEE 754 bits (an all-ones
   exponent is an infinity or a NaN), not by isfinite, so that the check
   holds under -ffast-math, which lets a compiler assume every value finite. */
static int ${name}_finite(double v)
{
    union { double d; unsigned long long u; } bits;
    bits.u = 0;
    bits.d = v;
    return (bits.u & 0x7FF0000000000000ULL) != 0x7FF0000000000000ULL;
}

/* A quiet NaN, built from its bits for the same reason. */
static double ${name}_nan(void)
{
    union { double d; unsigned long long u; } bits;
    bits.u = 0x7FF8000000000000ULL;
    return bits.d;
}

/* Solve M u = F in place for symmetric positive definite M (NU*NU,
   row-major), reading only its lower triangle: M = L L^T with L stored
   over that triangle, and F becomes u. Returns 0, or j + 1 when pivot j
   is not positive (or not a number). */
static int ${name}_cholesky_solve(double *M, double *F)
{
    const int k = ${prefix}_NU;
    int i, j, s;
    for (j = 0; j < k; ++j) {
        double d = M[j*k + j];
        for (s = 0; s < j; ++s) {
            d -= M[j*k + s]*M[j*k + s];
        }
        if (!(d > 0.0)) {
            return j + 1;
        }
        d = sqrt(d);
        M[j*k + j] = d;
        for (i = j + 1; i < k; ++i) {
            double v = M[i*k + j];
            for (s = 0; s < j; ++s) {
                v -= M[i*k + s]*M[j*k + s];
            }
            M[i*k + j] = v/d;
        }
    }
    for (i = 0; i < k; ++i) {
        double v = F[i];
        for (s = 0; s < i; ++s) {
            v -= M[i*k + s]*F[s];
        }
        F[i] = v/M[i*k + i];
    }
    for (i = k - 1; i >= 0; --i) {
        double v = F[i];
        for (s = i + 1; s < k; ++s) {
            v -= M[s*k + i]*F[s];
        }
        F[i] = v/M[i*k + i];
    }
    return 0;
}

/* The end of rhs: xdot holds q' and F (its last NU entries), M the lower
   triangle of the mass matrix. Returns what rhs returns: -1 when an entry
   is not finite, before or after the solve, else the Cholesky solve's. */
static int ${name}_solved(double *M, double *xdot)
{
    const int k = ${prefix}_NU, n = ${prefix}_NX;
    int i, j, status = 0;
    for (i = 0; i < n; ++i) {
        if (!${name}_finite(xdot[i])) {
            status = -1;
        }
    }
    for (i = 0; i < k; ++i) {
        for (j = 0; j <= i; ++j) {
            if (!${name}_finite(M[i*k + j])) {
                status = -1;
            }
        }
    }
    if (status == 0) {
        status = ${name}_cholesky_solve(M, xdot + (n - k));
    }
    for (i = 0; status == 0 && i < n; ++i) {
        if (!${name}_finite(xdot[i])) {
            status = -1;
        }
    }
    if (status != 0) {
        for (i = 0; i < n; ++i) {
            xdot[i] = ${name}_nan();
        }
    }
    return status;
}
''')
