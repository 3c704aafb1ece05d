#include <stdio.h>
#include "sphere_on_turntable.h"

int main(void)
{
    double x[SPHERE_ON_TURNTABLE_NX] = {0};
    double p[SPHERE_ON_TURNTABLE_NP];
    double r[SPHERE_ON_TURNTABLE_NR] = {0};
    double xdot[SPHERE_ON_TURNTABLE_NX];
    const double dt = 1e-3;

    sphere_on_turntable_default_parameters(p);     /* M, a, I = 2/5 M a^2: the file's values */
    r[SPHERE_ON_TURNTABLE_R_OMEGA] = 2.0;          /* the plane turns at 2 rad/s */
    x[SPHERE_ON_TURNTABLE_X_DOT_X] = 0.1;          /* rolling along x at first */

    for (int step = 0; step < 5000; ++step) {      /* explicit Euler, 5 s */
        if (sphere_on_turntable_rhs(step * dt, x, p, r, xdot) != 0)
            return 1;                               /* undefined here: see docs/generated-code.md */
        for (int i = 0; i < SPHERE_ON_TURNTABLE_NX; ++i)
            x[i] += dt * xdot[i];
    }
    printf("x = %.4f, y = %.4f\n", x[SPHERE_ON_TURNTABLE_X_X], x[SPHERE_ON_TURNTABLE_X_Y]);
    return 0;
}
