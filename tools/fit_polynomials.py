#!/usr/bin/env python3
"""The polynomial fits behind two of the kernels' float functions, reproducible:

  lambda  kernels/brdf/ndf.h BECKMANN_L_P: L(a) = 1/sqrt(pi) - a erfcx(a) on [0, 4] as
          t^2 P(z), t = 1/(1 + a), z = 2.5 (t - 0.2) - 1, P of degree 12 fitted to L (1 + a)^2.
  cos     kernels/integrate/azimuth.h cos_arc: sin(u)/u as a polynomial of degree 5 in u^2 on
          |u| <= 1.65, u = x - pi/2.

Both are least-squares fits in relative error on Chebyshev nodes against mpmath (50 digits).
Prints the coefficients and the largest relative error in exact (double) arithmetic and in
float32 arithmetic as the device evaluates them.

  python3 tools/fit_polynomials.py lambda|cos      (needs numpy and mpmath: pip install)
"""
import sys

import mpmath as mp
import numpy as np

mp.mp.dps = 50
f32 = np.float32


def horner32(coefs, x):
    """Horner in float32 with a fused multiply-add per step, as the device contracts it."""
    q = np.full_like(x, f32(coefs[-1]))
    for c in coefs[-2::-1]:
        q = (np.float64(q) * np.float64(x) + np.float64(f32(c))).astype(f32)
    return q


def fit_lambda():
    def L(a):
        a = mp.mpf(a)
        return 1 / mp.sqrt(mp.pi) - a * mp.erfc(a) * mp.exp(a * a)

    tlo, deg, n = 0.2, 12, 1200
    z = -np.cos(np.pi * (np.arange(n) + 0.5) / n)
    t = tlo + (1 - tlo) * (z + 1) / 2
    a = 1 / t - 1
    y = np.array([float(L(x) * (1 + x) ** 2) for x in a])
    v = np.polynomial.chebyshev.chebvander(z, deg) / y[:, None]
    c, *_ = np.linalg.lstsq(v, np.ones(n), rcond=None)
    p = np.polynomial.chebyshev.cheb2poly(c)
    xs = np.linspace(0, 4, 20001)
    ref = np.array([float(L(x)) for x in xs])
    t = 1 / (1 + xs)
    exact = np.polyval(p[::-1], 2.5 * (t - tlo) - 1) * t * t
    x32 = xs.astype(f32)
    t32 = (f32(1) / (f32(1) + x32)).astype(f32)
    dev = (horner32(p, (f32(2.5) * (t32 - f32(tlo)) - f32(1)).astype(f32)) * (t32 * t32)).astype(f32)
    ref32 = np.array([float(L(float(x))) for x in x32])
    print("P (ascending powers of z):")
    print(",\n".join("  RC(%.17g)" % v for v in p))
    print("largest relative error: exact arithmetic %.2e, float32 %.2e (uncompensated t)"
          % (np.abs(exact / ref - 1).max(), np.abs(dev / ref32 - 1).max()))


def fit_cos():
    umax, deg, n = 1.65, 5, 2000
    u = umax * (1 - np.cos(np.pi * (np.arange(n) + 0.5) / n)) / 2 + 1e-9
    y = np.array([float(mp.sin(x) / x) for x in u])
    v = np.vander(u * u, deg + 1, increasing=True) / y[:, None]
    c, *_ = np.linalg.lstsq(v, np.ones(n), rcond=None)
    uu = np.linspace(1e-3, umax, 100001)
    exact = np.polyval(c[::-1], uu * uu) * uu
    p1 = f32(np.pi / 2)
    p2 = f32(np.pi / 2 - np.float64(p1))
    x = np.linspace(0, np.pi, 400001).astype(f32)
    u32 = ((x - p1).astype(f32) - p2).astype(f32)
    dev = (-(np.float64(horner32(c, (u32 * u32).astype(f32))) * np.float64(u32))).astype(f32)
    print("sin(u)/u (ascending powers of u^2):")
    print(",\n".join("  RC(%.17g)" % v for v in c))
    print("pi/2 = %.17g + %.10g" % (p1, p2))
    print("largest relative error of sin in exact arithmetic %.2e; float32 cos on [0, pi]: %.2e absolute"
          % (np.abs(exact / np.sin(uu) - 1).max(), np.abs(dev - np.cos(x.astype(np.float64))).max()))


if __name__ == "__main__":
    which = sys.argv[1] if len(sys.argv) > 1 else ""
    if which == "lambda":
        fit_lambda()
    elif which == "cos":
        fit_cos()
    else:
        sys.exit(__doc__)
