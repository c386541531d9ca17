#!/usr/bin/env python3
"""How a sheared particle lattice changes the SPH pressure gradient, and what that does to a wave.

On a simple cubic lattice of spacing d, the SPH gradient of a linear field p is M^T grad p with
M = sum_j V_j (x_j - x_i) (x) grad W_ij, which the scalar lattice correction C makes exact at rest
(C M = I). Sheared by a strain E, M changes to first order: dM = T : E. Under gravity the pressure
gradient is rho g, so the plain gradient pushes a sheared lattice with C g dM, a force
proportional to the local strain: the particles resist shear like an elastic solid. This script
sums T for the Wendland C2 kernel at the given supports H (in spacings) and, by the Rayleigh
quotient of the linear standing wave that ParaFluid's validation runs (tank 1 m long, 0.5 m deep,
first mode), the relative change of its frequency that the force gives. It also prints the
cubic lattice's two shear moduli under a uniform pressure p (the symmetric force's other lattice
term, 2 p_i sum_j V_j grad W_ij), relative to p: a negative one means the lattice is unstable under
pressure. Nothing here is fitted to the measured frequencies (Testing/Benchmarks/README.md,
"Standing wave").

Usage: /usr/bin/python3 Testing/Benchmarks/lattice_gradient_gain.py [H ...]   (default 2 2.8 3 3.5 4)
"""
import sys

import numpy as np


def wendland_c2(r, support):
    """Wendland C2 in 3-D, normalised, with compact support `support`."""
    q = r / support
    return np.where(q < 1.0, 21.0 / (2.0 * np.pi * support**3) * (1.0 - q) ** 4 * (1.0 + 4.0 * q), 0.0)


def wendland_c2_slope_over_r(r, support):
    """(dW/dr) / r of Wendland C2."""
    q = r / support
    return np.where(q < 1.0, -20.0 * 21.0 / (2.0 * np.pi * support**5) * (1.0 - q) ** 3, 0.0)


def neighbour_offsets(support):
    """Lattice offsets (unit spacing) inside the support, and each neighbour's volume V = m / rho."""
    reach = int(np.ceil(support))
    axis = np.arange(-reach, reach + 1)
    offsets = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T.astype(float)
    offsets = offsets[np.linalg.norm(offsets, axis=1) > 0.0]
    # The rest lattice's summed density is rho0: V = 1 / sum_j W (the particle itself included).
    volume = 1.0 / (wendland_c2(np.linalg.norm(offsets, axis=1), support).sum() + wendland_c2(0.0, support))
    return offsets, volume


def first_moment_z(offsets, volume, support, strain):
    """sum_j V (z_j - z_i) grad_i W_ij on the lattice strained by x' = (I + strain) x."""
    x = offsets @ (np.eye(3) + strain).T  # x_j - x_i
    r = np.linalg.norm(x, axis=1)
    grad = wendland_c2_slope_over_r(r, support)[:, None] * (-x)  # grad_i W_ij, x_ij = -x
    return (volume * x[:, 2:3] * grad).sum(axis=0)


def strain_gain(support):
    """C and T[a, b, c] = d (sum_j V (z_j - z_i) grad W)_a / d E_bc."""
    offsets, volume = neighbour_offsets(support)
    rest = first_moment_z(offsets, volume, support, np.zeros((3, 3)))
    step = 1e-5
    gain = np.zeros((3, 3, 3))
    for b in range(3):
        for c in range(3):
            strain = np.zeros((3, 3))
            strain[b, c] = step
            gain[:, b, c] = (first_moment_z(offsets, volume, support, strain) -
                             first_moment_z(offsets, volume, support, -strain)) / (2.0 * step)
    return 1.0 / rest[2], gain


def wave_frequency_shift(support, g=9.81, length=1.0, depth=0.5, cells=400):
    """d omega / omega of the first standing wave from the force C g (T : grad xi) (Rayleigh)."""
    correction, gain = strain_gain(support)
    k = np.pi / length
    x = (np.arange(cells) + 0.5) * length / cells
    z = (np.arange(cells) + 0.5) * depth / cells
    X, Z = np.meshgrid(x, z, indexing="ij")
    s = np.sinh(k * depth)
    # Displacement of the linear mode with unit surface amplitude, eta = cos(k x) (z from the floor).
    xi_x = -np.cosh(k * Z) / s * np.sin(k * X)
    xi_z = np.sinh(k * Z) / s * np.cos(k * X)
    grad = np.zeros((3, 3) + X.shape)  # d xi_b / d x_c
    grad[0, 0] = -k * np.cosh(k * Z) / s * np.cos(k * X)
    grad[0, 2] = -k * np.sinh(k * Z) / s * np.sin(k * X)
    grad[2, 0] = -k * np.sinh(k * Z) / s * np.sin(k * X)
    grad[2, 2] = k * np.cosh(k * Z) / s * np.cos(k * X)
    force = correction * g * np.einsum("abc,bc...->a...", gain, grad)
    area = (length / cells) * (depth / cells)
    work = -(force[0] * xi_x + force[2] * xi_z).sum() * area
    potential = g * 0.5 * length  # g times the integral of eta^2 over the tank
    return np.sqrt(1.0 + work / potential) - 1.0


def shear_moduli(support, cells=24, amplitude=1e-3):
    """The cubic lattice's shear moduli under uniform pressure p with the force -2 p sum_j V grad W,
    relative to p: C44 (u_x = a sin(k z)) and C' = (C11 - C12) / 2 (a transverse wave along the
    diagonal), from a periodic lattice of `cells`^3 particles."""
    offsets, volume = neighbour_offsets(support)
    axis = np.arange(cells) + 0.5
    X, Y, Z = np.meshgrid(axis, axis, axis, indexing="ij")
    rest = np.c_[X.ravel(), Y.ravel(), Z.ravel()]
    k = 2.0 * np.pi / cells
    index = np.arange(cells**3).reshape(cells, cells, cells)
    I, J, K = np.unravel_index(np.arange(cells**3), (cells, cells, cells))
    moduli = []
    for mode in ("xz", "diagonal"):
        u = np.zeros_like(rest)
        if mode == "xz":
            phase = k * rest[:, 2]
            u[:, 0] = amplitude * np.sin(phase)
        else:
            phase = k * (rest[:, 0] + rest[:, 2])
            u[:, 0] = amplitude * np.sin(phase) / np.sqrt(2.0)
            u[:, 2] = -amplitude * np.sin(phase) / np.sqrt(2.0)
        x = rest + u
        force = np.zeros_like(x)
        for o in offsets.astype(int):
            j = index[(I + o[0]) % cells, (J + o[1]) % cells, (K + o[2]) % cells]
            xij = x - x[j]
            xij -= cells * np.round(xij / cells)
            r = np.linalg.norm(xij, axis=1)
            force += -2.0 * volume * wendland_c2_slope_over_r(r, support)[:, None] * xij
        if mode == "xz":
            along = force[:, 0]
            wavenumber2 = k * k
        else:
            along = (force[:, 0] - force[:, 2]) / np.sqrt(2.0)
            wavenumber2 = 2.0 * k * k
        amplitude_out = 2.0 * np.mean(along * np.sin(phase))
        moduli.append(-amplitude_out / (wavenumber2 * amplitude))
    return moduli


def main():
    supports = [float(a) for a in sys.argv[1:]] or [2.0, 2.8, 3.0, 3.5, 4.0]
    print("support H  C        standing wave d omega / omega   C44 / p   C' / p")
    for support in supports:
        correction, _ = strain_gain(support)
        c44, c_prime = shear_moduli(support)
        print(f"{support:9.2f}  {correction:.4f}  {100.0 * wave_frequency_shift(support):+8.2f} %"
              f"                     {c44:+.4f}   {c_prime:+.4f}")


if __name__ == "__main__":
    main()
