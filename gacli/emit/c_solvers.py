"""The C source's dense LU solve, written as loops: the reactions of a large system solve with it."""

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
