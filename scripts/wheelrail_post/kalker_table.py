"""Kalker's creep coefficients C11, C22, C23 of the linear theory of rolling
contact for elliptic patches, and their interpolation in a/b and nu.

The table is Kalker's (J. J. Kalker, Three-dimensional elastic bodies in
rolling contact, Kluwer 1990, Table E.3; first in his 1967 thesis, also in
Johnson, Contact Mechanics, Table 8.1), as CONTACT carries it (Vtech CMCC,
E. A. H. Vollebregt; github eve70a/CONTACT, src/m_hertz.f90, subroutine
linrol, Apache 2.0; the numbers only): for g = a/b <= 1
(a along the rolling direction) and for g = b/a <= 1, rows g = 0.1 .. 1.0,
each coefficient at nu = 0, 0.25, 0.5. The a/b and b/a halves meet at
a = b. Within a row pair the interpolation is linear in g, as CONTACT's.

In nu two interpolations are offered: linear between nu = 0.25 and 0.5
(interpolate), and CONTACT's, a parabola in 1 / C through nu = 0, 0.25, 0.5
(interpolate_contact). For SPEC 8's b/a = 0.752, nu = 0.3 they give
C11 4.656 and 4.623 (SPEC 8's 4.62 is CONTACT's), C22 4.181 and 4.176,
C23 1.888 and 1.885; the checks use CONTACT's.

C33 (spin moment from spin) is not in CONTACT's table; it is not used.
"""
import math

# rows g = 0.1, 0.2, ..., 1.0; per row (C11, C22, C23), each at nu 0, 0.25, 0.5
A_OVER_B = [  # a/b <= 1 (patch wider than long)
    ((2.51, 3.31, 4.85), (2.51, 2.52, 2.53), (.334, .473, .731)),
    ((2.59, 3.37, 4.81), (2.59, 2.63, 2.66), (.483, .603, .809)),
    ((2.68, 3.44, 4.80), (2.68, 2.75, 2.81), (.607, .715, .889)),
    ((2.78, 3.53, 4.82), (2.78, 2.88, 2.98), (.720, .823, .977)),
    ((2.88, 3.62, 4.83), (2.88, 3.01, 3.14), (.827, .929, 1.07)),
    ((2.98, 3.72, 4.91), (2.98, 3.14, 3.31), (.930, 1.03, 1.18)),
    ((3.09, 3.81, 4.97), (3.09, 3.28, 3.48), (1.03, 1.14, 1.29)),
    ((3.19, 3.91, 5.05), (3.19, 3.41, 3.65), (1.13, 1.25, 1.40)),
    ((3.29, 4.01, 5.12), (3.29, 3.54, 3.82), (1.23, 1.36, 1.51)),
    ((3.40, 4.12, 5.20), (3.40, 3.67, 3.98), (1.33, 1.47, 1.63)),
]
B_OVER_A = [  # b/a <= 1 (patch longer than wide: the wheel-rail case of SPEC 8)
    ((10.7, 11.7, 12.9), (10.7, 12.8, 16.0), (12.2, 14.6, 18.0)),
    ((6.96, 7.78, 8.82), (6.96, 8.14, 9.79), (5.72, 6.63, 7.89)),
    ((5.57, 6.34, 7.34), (5.57, 6.40, 7.51), (3.79, 4.32, 5.01)),
    ((4.84, 5.57, 6.57), (4.84, 5.48, 6.31), (2.88, 3.24, 3.70)),
    ((4.37, 5.10, 6.11), (4.37, 4.90, 5.56), (2.35, 2.62, 2.96)),
    ((4.06, 4.78, 5.80), (4.06, 4.50, 5.04), (2.01, 2.23, 2.50)),
    ((3.82, 4.54, 5.58), (3.82, 4.21, 4.67), (1.76, 1.95, 2.18)),
    ((3.65, 4.36, 5.42), (3.65, 3.99, 4.39), (1.58, 1.75, 1.94)),
    ((3.51, 4.22, 5.30), (3.51, 3.81, 4.16), (1.44, 1.59, 1.77)),
    ((3.40, 4.12, 5.20), (3.40, 3.67, 3.98), (1.33, 1.47, 1.63)),
]
NAMES = ("C11", "C22", "C23")


def _row_values(a_over_b):
    """The three coefficients at nu = 0, 0.25, 0.5, linear in g between rows."""
    table, g = (A_OVER_B, a_over_b) if a_over_b <= 1.0 else (B_OVER_A, 1.0 / a_over_b)
    if not 0.1 <= g <= 1.0:
        raise ValueError("a/b = %g is outside the table (g = min(a/b, b/a) >= 0.1)" % a_over_b)
    i = min(int(10.0 * g - 0.005) - 1, 8)  # row of g = (i + 1) / 10 below g
    w = 10.0 * g - (i + 1)
    return [[(1.0 - w) * table[i][k][j] + w * table[i + 1][k][j] for j in range(3)]
            for k in range(3)]


def interpolate(a_over_b, nu):
    """C11, C22, C23 linear in g, then linear in nu between 0.25 and 0.5."""
    if not 0.25 <= nu <= 0.5:
        raise ValueError("nu = %g: the linear interpolation is for 0.25 <= nu <= 0.5" % nu)
    t = (nu - 0.25) / 0.25
    return dict(zip(NAMES, [(1.0 - t) * c[1] + t * c[2] for c in _row_values(a_over_b)]))


def interpolate_contact(a_over_b, nu):
    """C11, C22, C23 as CONTACT's linrol: linear in g, then 1 / C by the
    parabola through nu = 0, 0.25, 0.5."""
    out = []
    for c in _row_values(a_over_b):
        inv = ((nu - 0.25) * (nu - 0.5) * 8.0 / c[0] - (nu - 0.5) * nu * 16.0 / c[1]
               + nu * (nu - 0.25) * 8.0 / c[2])
        out.append(1.0 / inv)
    return dict(zip(NAMES, out))


def linear_forces(g_mod, a, b, coefficients, xi=0.0, eta=0.0, phi=0.0):
    """Kalker's linear theory (rolling3d.py's signs): F_x, F_y and the part
    of M_z from eta, -G c^3 (-C23 eta) (C33 is not tabulated here)."""
    c = math.sqrt(a * b)
    k = coefficients
    return (-g_mod * c * c * k["C11"] * xi,
            -g_mod * c * c * (k["C22"] * eta + c * k["C23"] * phi),
            g_mod * c ** 3 * k["C23"] * eta)
