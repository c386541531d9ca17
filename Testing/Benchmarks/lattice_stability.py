#!/usr/bin/env python3
"""Is a simple cubic particle lattice under uniform pressure stable against the SPH pressure force?

Under a uniform pressure p the momentum-conserving force -sum_j m (p_i/rho_i^2 + p_j/rho_j^2) grad W_ij
is the force of a pair potential 2 m p / rho^2 W(r), so a displacement wave u exp(i k.x) of the lattice
feels the dynamical matrix D(k) = sum_j (1 - cos k.x_j) grad grad W(x_j) (times 2 p V / rho). The
continuity equation answers only the part of u along g(k) = sum_j grad W(x_j) sin(k.x_j), with a
density change and a pressure c0^2 times stiffer; every displacement across g(k) (the transverse,
shearing waves) is held by D alone. The lattice is stable when D restricted to the plane across g(k)
has no negative eigenvalue for any k in the Brillouin zone. The smallest of those eigenvalues over k^2
is printed per kernel and support (spacing 1, normalised kernels, no fitted number), with the long-wave
shear moduli C44 (u along x, k along y) and C' (u along x - y, k along x + y) of the same matrix, which a
standing wave feels as a spurious elasticity (Testing/Benchmarks/README.md, "The pressure gradient on a
sheared lattice").

With --high-pass the 2 p_i term is δ-SPH's with SPHParameters::pushHighPass: less its Shepard mean over
the same kernel (self included), so D(k) becomes (1 - S(k)) D(k) with S(k) = sum_j W(x_j) cos(k.x_j) /
sum_j W(x_j); S is between 0 and 1 for a kernel whose Fourier transform is positive (Wendland's), so a
stable lattice stays stable and the long-wave moduli go to zero.

Usage: /usr/bin/python3 Testing/Benchmarks/lattice_stability.py [--high-pass] [kernel:support[:density_kernel:support] ...]
       (kernel: wendland (δ-SPH's Wendland C2), cubic (DFSPH's and Müller's cubic spline) or quintic
       (Morris et al. 1997's M6 spline); the density kernel, whose response holds the compression, is
       the same kernel at the same support unless given: quintic:2.8:wendland:3 is a quintic
       2 p_i term inside δ-SPH's Wendland kernel at 3 spacings)
"""
import itertools
import sys

import numpy as np

SHAPES = {
    "wendland": lambda q: np.maximum(1.0 - q, 0.0) ** 4 * (1.0 + 4.0 * q),
    "cubic": lambda q: np.where(q < 0.5, 1.0 - 6.0 * q * q + 6.0 * q**3, 2.0 * np.maximum(1.0 - q, 0.0) ** 3),
    "quintic": lambda q: (np.maximum(1.0 - q, 0.0) ** 5 - 6.0 * np.maximum(2.0 / 3.0 - q, 0.0) ** 5 +
                          15.0 * np.maximum(1.0 / 3.0 - q, 0.0) ** 5),
}


def radial_derivatives(kernel, support, r, step=1e-5):
    """dW/dr and d2W/dr2 of the normalised 3-D kernel with the given support, by central differences."""
    shape = SHAPES[kernel]
    q = np.linspace(0.0, 1.0, 200001)
    scale = 1.0 / (4.0 * np.pi * np.trapz(shape(q) * q * q, q) * support**3)
    w = lambda x: scale * shape(x / support)
    return (w(r + step) - w(r - step)) / (2.0 * step), (w(r + step) - 2.0 * w(r) + w(r - step)) / step**2


def shepard_mean(kernel, support):
    """S(k): the lattice's kernel-weighted mean of cos k.x_j, the particle itself included."""
    reach = int(np.ceil(support))
    points = [np.array(o, float) for o in itertools.product(range(-reach, reach + 1), repeat=3)
              if np.linalg.norm(o) < support]
    weights = np.array([SHAPES[kernel](np.linalg.norm(x) / support) for x in points])
    points = np.array(points)
    return lambda k: float(weights @ np.cos(points @ k)) / float(weights.sum())


def analyse(kernel, support, density_kernel, density_support, high_pass=False, samples=13):
    reach = int(np.ceil(max(support, density_support)))
    smooth = shepard_mean(kernel, support) if high_pass else (lambda k: 0.0)
    offsets = [np.array(o, float) for o in itertools.product(range(-reach, reach + 1), repeat=3)
               if 0.0 < np.linalg.norm(o) < max(support, density_support)]
    terms = []
    for x in offsets:
        r = np.linalg.norm(x)
        e = x / r
        first, second = radial_derivatives(kernel, support, r) if r < support else (0.0, 0.0)
        hessian = second * np.outer(e, e) + first / r * (np.eye(3) - np.outer(e, e))
        density_slope = radial_derivatives(density_kernel, density_support, r)[0] if r < density_support else 0.0
        terms.append((x, hessian, density_slope * e))

    def matrices(k):
        d = sum((1.0 - np.cos(k @ x)) * h for x, h, _ in terms) * (1.0 - smooth(k))
        g = sum(np.sin(k @ x) * s for x, _, s in terms)
        return d, g

    worst, where = np.inf, None
    for k in itertools.product(np.linspace(0.0, np.pi, samples), repeat=3):
        k = np.array(k)
        if not (k[0] >= k[1] >= k[2]) or not k.any():  # the cubic lattice's symmetry: one wedge
            continue
        d, g = matrices(k)
        if np.linalg.norm(g) > 1e-9:
            n = g / np.linalg.norm(g)
            a = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
            t1 = a - n * (a @ n)
            t1 /= np.linalg.norm(t1)
            plane = np.stack([t1, np.cross(n, t1)], axis=1)
            smallest = np.linalg.eigvalsh(plane.T @ d @ plane).min()
        else:
            smallest = np.linalg.eigvalsh(d).min()
        if smallest / (k @ k) < worst:
            worst, where = smallest / (k @ k), k / np.pi
    small = 0.05
    d, _ = matrices(np.array([0.0, small, 0.0]))
    c44 = d[0, 0] / small**2
    d, _ = matrices(np.array([small, small, 0.0]) / np.sqrt(2.0))
    u = np.array([1.0, -1.0, 0.0]) / np.sqrt(2.0)
    c_prime = u @ d @ u / small**2
    return worst, where, c44, c_prime


def main():
    high_pass = "--high-pass" in sys.argv[1:]
    cases = [a for a in sys.argv[1:] if a != "--high-pass"] or ["wendland:2.75", "wendland:2.8", "wendland:2.85", "wendland:2.9", "wendland:2.95",
                             "wendland:3", "wendland:3.2", "wendland:3.5", "wendland:4", "quintic:2.8:wendland:3",
                             "quintic:3:wendland:3", "cubic:2"]
    print("kernel     support  smallest eigenvalue / k^2 (at k / pi)      C44        C'       verdict")
    for case in cases:
        kernel, support, *density = case.split(":")  # the density kernel: the same one unless given
        density_kernel, density_support = (density[0], float(density[1])) if density else (kernel, float(support))
        worst, where, c44, c_prime = analyse(kernel, float(support), density_kernel, density_support, high_pass)
        verdict = "stable" if worst >= -1e-6 else "unstable"
        print(f"{kernel:9s}  {float(support):6.2f}   {worst:+.5f} at {np.round(where, 2)}   "
              f"{c44:+.5f}  {c_prime:+.5f}   {verdict}")


if __name__ == "__main__":
    main()
