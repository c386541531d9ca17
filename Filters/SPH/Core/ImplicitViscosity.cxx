// DFSPH's implicit viscosity (Weiler, Koschier, Brand & Bender, "A Physically Consistent Implicit
// Viscosity Solver for SPH Fluids", Computer Graphics Forum 2018). The predicted velocities v* are
// replaced by the solution of
//     v_i - dt A(v)_i = v*_i,   A(v)_i = 2 (d + 2) nu sum_j V_j (v_ij . x_ij) / (r^2 + 0.01 h^2) grad W_ij,
// the viscous operator of Monaghan (2005) evaluated at the end of the step, so any viscosity is
// stable at the step the pressure solve allows (explicitly the step would have to stay below
// about 0.03 h^2 / nu: 4 ms for water at 1 cm spacing, but 0.4 us for honey).
//
// The system is solved matrix-free: rows scaled by V_i make it symmetric positive definite (the
// pair coefficients carry V_i V_j), so Jacobi-preconditioned conjugate gradients apply. Two
// implementations of the same iteration: a hand-written one on plain arrays with OpenMP
// reductions, and Eigen's ConjugateGradient on a matrix-free operator; ParaFluidSPHBenchmark
// measures both (SPHParameters::viscositySolver picks one; the faster is the default).
#include "parafluid/sph/DFSPHSolver.h"

#include "parafluid/common/Kernels.h"
#include "parafluid/sph/WallMirrors.h"
#include "private/NeighbourCandidates.h"
#include "private/SimulationParts.h"
#include "private/WallImages.h"

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

namespace parafluid::sph
{
namespace detail
{
/// The viscous system M v = V v* (M = V (I - dt A)) as an operator on 3n-vectors laid out as all
/// x components, then all y, then all z (so each component is a channel of the neighbour pass).
struct ViscousOperator
{
  const NeighbourGrid* grid = nullptr;
  ParticleState* state = nullptr;
  const SPHParameters* p = nullptr;
  float dt = 0.0f;
  float laplacianCorrection = 1.0f; // see latticeLaplacianCorrection
  std::vector<float> volume;        // V_i = m / rho_i
  std::vector<float> diagonal;
  std::size_t n = 0;

  /// Pair coefficient 10 nu V_j F / (r^2 + eta^2), F = (dW/dr) / r of the cubic spline.
  template<class Visit>
  void forEachRow(const float* x, Visit&& visit) const
  {
    const CubicSplineKernel w(p->smoothingLength);
    const float eta2 = 0.01f * 0.25f * w.h2;
    const float nu10 = 10.0f * p->kinematicViscosity * laplacianCorrection;
    forEachParticleByCell(
      *grid, *state, p->smoothingLength, threadCount(*p), { x, x + n, x + 2 * n, volume.data() },
      [&](CandidateBuffer& c, std::uint32_t i)
      {
        const float position[3] = { state->x[i], state->y[i], state->z[i] };
        const float value[3] = { x[i], x[n + i], x[2 * n + i] };
        float sum[3] = { 0.0f, 0.0f, 0.0f }, diag[3] = { 0.0f, 0.0f, 0.0f };
        auto add = [&](const float q[3], const float vq[3], const float t[3], const float scale[3])
        {
          const std::uint32_t count = c.findHits(q, w.h2);
          float sx = 0.0f, sy = 0.0f, sz = 0.0f, dx2 = 0.0f, dy2 = 0.0f, dz2 = 0.0f;
          const float *px = c.x.data(), *py = c.y.data(), *pz = c.z.data(), *r2 = c.distanceSquared.data();
          const float *ux = c.channel[0].data(), *uy = c.channel[1].data(), *uz = c.channel[2].data();
          const float* vj = c.channel[3].data();
          const std::uint32_t* hits = c.hits.data();
#pragma omp simd reduction(+ : sx, sy, sz, dx2, dy2, dz2)
          for (std::uint32_t k = 0; k < count; ++k)
          {
            const std::uint32_t j = hits[k];
            const float dx = q[0] - px[j], dy = q[1] - py[j], dz = q[2] - pz[j];
            const float r = std::sqrt(r2[j]);
            const float qr = r * w.inverseH;
            const float d = 1.0f - qr;
            const float inner = w.coefficient * w.inverseH * w.inverseH * (18.0f * qr - 12.0f);
            const float outer = -6.0f * w.coefficient * w.inverseH * d * d / std::max(r, 1e-30f);
            const float gradient = qr <= 0.5f ? inner : outer;
            const float coefficient = nu10 * vj[j] * gradient / (r2[j] + eta2);
            const float approach =
              (vq[0] - t[0] * ux[j]) * dx + (vq[1] - t[1] * uy[j]) * dy + (vq[2] - t[2] * uz[j]) * dz;
            sx += coefficient * approach * dx;
            sy += coefficient * approach * dy;
            sz += coefficient * approach * dz;
            dx2 += coefficient * dx * dx;
            dy2 += coefficient * dy * dy;
            dz2 += coefficient * dz * dz;
          }
          sum[0] += scale[0] * sx;
          sum[1] += scale[1] * sy;
          sum[2] += scale[2] * sz;
          diag[0] += dx2;
          diag[1] += dy2;
          diag[2] += dz2;
        };
        forEachWallImage(position, value, *p,
                         [&](const float* q, const float* vq, const float* t, const float* scale, bool)
                         { add(q, vq, t, scale); });
        visit(i, value, sum, diag);
      });
  }

  /// y = M x.
  void apply(const float* x, float* y) const
  {
    forEachRow(x,
               [&](std::uint32_t i, const float* value, const float* sum, const float*)
               {
                 for (int a = 0; a < 3; ++a)
                 {
                   y[a * n + i] = volume[i] * (value[a] - dt * sum[a]);
                 }
               });
  }

  /// y = M x and the diagonal of M in one neighbour pass (the diagonal depends on the positions
  /// only, so it comes free with the first product).
  void applyAndComputeDiagonal(const float* x, float* y)
  {
    diagonal.resize(3 * n);
    forEachRow(x,
               [&](std::uint32_t i, const float* value, const float* sum, const float* diag)
               {
                 for (int a = 0; a < 3; ++a)
                 {
                   y[a * n + i] = volume[i] * (value[a] - dt * sum[a]);
                   diagonal[a * n + i] = volume[i] * (1.0f - dt * diag[a]);
                 }
               });
  }
};

namespace
{
double dot(const std::vector<float>& a, const std::vector<float>& b, int threads)
{
  const auto n = static_cast<std::int64_t>(a.size());
  double sum = 0.0;
#pragma omp parallel for simd schedule(static) reduction(+ : sum) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i)
  {
    sum += static_cast<double>(a[i]) * b[i];
  }
  return sum;
}

/// Jacobi-preconditioned CG on plain arrays until |r| <= tolerance |b|; x holds the start and
/// returns the solution (a start of all zeros skips the first product: M 0 = 0).
int handWrittenCG(const ViscousOperator& op, const std::vector<float>& b, std::vector<float>& x, float tolerance,
                  int maxIterations, int threads)
{
  const auto size = static_cast<std::int64_t>(b.size());
  std::vector<float> r(b.size()), z(b.size()), d(b.size()), q(b.size(), 0.0f);
  if (std::any_of(x.begin(), x.end(), [](float value) { return value != 0.0f; }))
  {
    op.apply(x.data(), q.data());
  }
#pragma omp parallel for simd schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < size; ++k)
  {
    r[k] = b[k] - q[k];
    z[k] = r[k] / op.diagonal[k];
    d[k] = z[k];
  }
  const double limit = static_cast<double>(tolerance) * tolerance * dot(b, b, threads);
  double rz = dot(r, z, threads);
  int iterations = 0;
  while (iterations < maxIterations && dot(r, r, threads) > limit)
  {
    op.apply(d.data(), q.data());
    const double dq = dot(d, q, threads);
    if (!(dq > 0.0))
    {
      break;
    }
    const auto alpha = static_cast<float>(rz / dq);
#pragma omp parallel for simd schedule(static) num_threads(threads)
    for (std::int64_t k = 0; k < size; ++k)
    {
      x[k] += alpha * d[k];
      r[k] -= alpha * q[k];
      z[k] = r[k] / op.diagonal[k];
    }
    const double rzNext = dot(r, z, threads);
    const auto beta = static_cast<float>(rzNext / rz);
    rz = rzNext;
#pragma omp parallel for simd schedule(static) num_threads(threads)
    for (std::int64_t k = 0; k < size; ++k)
    {
      d[k] = z[k] + beta * d[k];
    }
    ++iterations;
  }
  return iterations;
}
} // namespace
} // namespace detail
} // namespace parafluid::sph

// Eigen's matrix-free interface: a matrix type whose product with a vector calls the operator.
namespace parafluid::sph::detail
{
class ViscousMatrix;
}
namespace Eigen::internal
{
template<>
struct traits<parafluid::sph::detail::ViscousMatrix> : public traits<Eigen::SparseMatrix<float>>
{
};
} // namespace Eigen::internal

namespace parafluid::sph::detail
{
class ViscousMatrix : public Eigen::EigenBase<ViscousMatrix>
{
public:
  using Scalar = float;
  using RealScalar = float;
  using StorageIndex = int;
  enum
  {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };
  explicit ViscousMatrix(const ViscousOperator& op)
    : Op(&op)
  {
  }
  Eigen::Index rows() const { return static_cast<Eigen::Index>(3 * this->Op->n); }
  Eigen::Index cols() const { return this->rows(); }
  template<typename Rhs>
  Eigen::Product<ViscousMatrix, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const
  {
    return Eigen::Product<ViscousMatrix, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }
  const ViscousOperator& op() const { return *this->Op; }

private:
  const ViscousOperator* Op;
};

/// Eigen's preconditioner interface over the operator's diagonal.
class ViscousJacobi
{
public:
  ViscousJacobi() = default;
  template<typename M>
  ViscousJacobi& analyzePattern(const M&)
  {
    return *this;
  }
  template<typename M>
  ViscousJacobi& factorize(const M& m)
  {
    return this->compute(m);
  }
  template<typename M>
  ViscousJacobi& compute(const M& m)
  {
    const auto& d = m.op().diagonal;
    this->Inverse = Eigen::Map<const Eigen::VectorXf>(d.data(), static_cast<Eigen::Index>(d.size())).cwiseInverse();
    return *this;
  }
  template<typename Rhs>
  Eigen::VectorXf solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    return this->Inverse.cwiseProduct(b.derived());
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
  Eigen::VectorXf Inverse;
};
} // namespace parafluid::sph::detail

namespace Eigen::internal
{
template<typename Rhs>
struct generic_product_impl<parafluid::sph::detail::ViscousMatrix, Rhs, SparseShape, DenseShape, GemvProduct>
  : generic_product_impl_base<parafluid::sph::detail::ViscousMatrix, Rhs,
                              generic_product_impl<parafluid::sph::detail::ViscousMatrix, Rhs>>
{
  using Scalar = typename Product<parafluid::sph::detail::ViscousMatrix, Rhs>::Scalar;
  template<typename Dest>
  static void scaleAndAddTo(Dest& dst, const parafluid::sph::detail::ViscousMatrix& lhs, const Rhs& rhs,
                            const Scalar& alpha)
  {
    const Eigen::VectorXf x = rhs; // contiguous copy for the neighbour pass
    Eigen::VectorXf y(x.size());
    lhs.op().apply(x.data(), y.data());
    dst.noalias() += alpha * y;
  }
};
} // namespace Eigen::internal

namespace parafluid::sph
{
int DFSPHSolver::solveViscosity(SimulationParts& sim, float dt)
{
  const SPHParameters& p = sim.parameters();
  ParticleState& s = sim.state();
  const std::size_t n = s.size();
  if (!(p.kinematicViscosity > 0.0f) || n == 0)
  {
    return 0;
  }
  const int threads = detail::threadCount(p);
  detail::ViscousOperator op;
  op.grid = &sim.grid();
  op.state = &s;
  op.p = &p;
  op.dt = dt;
  op.n = n;
  op.laplacianCorrection = sim.laplacianCorrection();
  op.volume.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    op.volume[i] = p.particleMass / s.density[i];
  }
  // Solved for the change of velocity dv = v - v*: M dv = V v* - M v*, from dv = 0, so that the
  // tolerance is relative to what viscosity changes in this step (relative to V v* itself, a small
  // viscous change would already count as converged before the first iteration).
  std::vector<float> current(3 * n), product(3 * n), b(3 * n), x(3 * n, 0.0f);
  const float* v[3] = { s.vx.data(), s.vy.data(), s.vz.data() };
  for (int a = 0; a < 3; ++a)
  {
    std::copy(v[a], v[a] + n, current.begin() + static_cast<std::ptrdiff_t>(a * n));
  }
  op.applyAndComputeDiagonal(current.data(), product.data());
  for (int a = 0; a < 3; ++a)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      b[a * n + i] = op.volume[i] * v[a][i] - product[a * n + i];
    }
  }
  int iterations = 0;
  if (p.viscositySolver == ViscositySolver::EigenCG)
  {
    const detail::ViscousMatrix matrix(op);
    Eigen::ConjugateGradient<detail::ViscousMatrix, Eigen::Lower | Eigen::Upper, detail::ViscousJacobi> cg;
    cg.setTolerance(p.viscosityTolerance);
    cg.setMaxIterations(p.maxPressureIterations);
    cg.compute(matrix);
    const Eigen::Map<const Eigen::VectorXf> rhs(b.data(), static_cast<Eigen::Index>(b.size()));
    Eigen::Map<Eigen::VectorXf> guess(x.data(), static_cast<Eigen::Index>(x.size()));
    const Eigen::VectorXf solution = cg.solveWithGuess(rhs, Eigen::VectorXf(guess));
    guess = solution;
    iterations = static_cast<int>(cg.iterations());
  }
  else
  {
    iterations = detail::handWrittenCG(op, b, x, p.viscosityTolerance, p.maxPressureIterations, threads);
  }
  for (int a = 0; a < 3; ++a)
  {
    float* target = a == 0 ? s.vx.data() : a == 1 ? s.vy.data() : s.vz.data();
    for (std::size_t i = 0; i < n; ++i)
    {
      target[i] += x[a * n + i];
    }
  }
  return iterations;
}
} // namespace parafluid::sph
