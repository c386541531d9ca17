#include "ConjugateGradients.h"

#include <algorithm>
#include <cmath>

namespace parafluid::clouds::detail
{
namespace
{
double dot(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0.0;
  const long long n = static_cast<long long>(a.size());
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (long long i = 0; i < n; ++i)
  {
    sum += a[i] * b[i];
  }
  return sum;
}

void subtractMean(std::vector<double>& v)
{
  double sum = 0.0;
  const long long n = static_cast<long long>(v.size());
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (long long i = 0; i < n; ++i)
  {
    sum += v[i];
  }
  const double mean = sum / static_cast<double>(n);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < n; ++i)
  {
    v[i] -= mean;
  }
}
} // namespace

SolveReport conjugateGradients(const LinearMap& A, const LinearMap& preconditioner, const std::vector<double>& b,
                               std::vector<double>& x, double tolerance, int maxIterations, bool removeMean,
                               double scale, const LinearMapDot& ADot, std::array<std::vector<double>, 4>* scratch)
{
  const long long n = static_cast<long long>(b.size());
  std::array<std::vector<double>, 4> local;
  std::array<std::vector<double>, 4>& work = scratch ? *scratch : local;
  for (std::vector<double>& v : work)
  {
    v.resize(n);
  }
  std::vector<double>&r = work[0], &z = work[1], &p = work[2], &q = work[3];
  A(x, q);
  double rr = 0.0, bb = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr, bb)
  for (long long i = 0; i < n; ++i)
  {
    r[i] = b[i] - q[i];
    rr += r[i] * r[i];
    bb += b[i] * b[i];
  }
  const double bNorm = std::max(std::sqrt(bb), scale);
  SolveReport report;
  if (bNorm == 0.0)
  {
    std::fill(x.begin(), x.end(), 0.0);
    return report;
  }
  report.residual = std::sqrt(rr) / bNorm;
  if (report.residual <= tolerance)
  {
    return report;
  }
  preconditioner(r, z);
  if (removeMean)
  {
    subtractMean(z);
  }
  p = z;
  double rz = dot(r, z);
  while (report.residual > tolerance && report.iterations < maxIterations)
  {
    // q = A p and p . q, in one pass where the operator offers it.
    double pq = 0.0;
    if (ADot)
    {
      pq = ADot(p, q);
    }
    else
    {
      A(p, q);
      pq = dot(p, q);
    }
    const double alpha = rz / pq;
    rr = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : rr)
    for (long long i = 0; i < n; ++i)
    {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      rr += r[i] * r[i];
    }
    ++report.iterations;
    report.residual = std::sqrt(rr) / bNorm;
    if (report.residual <= tolerance)
    {
      break;
    }
    preconditioner(r, z);
    if (removeMean)
    {
      subtractMean(z);
    }
    const double rzNext = dot(r, z);
    const double beta = rzNext / rz;
#pragma omp parallel for schedule(static)
    for (long long i = 0; i < n; ++i)
    {
      p[i] = z[i] + beta * p[i];
    }
    rz = rzNext;
  }
  return report;
}
} // namespace parafluid::clouds::detail
