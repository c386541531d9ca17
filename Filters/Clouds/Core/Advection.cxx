// Semi-Lagrangian advection on the staggered grid (Stam 1999), the MacCormack correction (Selle
// et al. 2008) for the velocity, and for the scalars a conservative variant (after Lentine,
// Aanjaneya & Fedkiw 2011) sharpened by BFECC (Kim, Liu, Llamas & Rossignac 2005) around the
// conservative step, with a mass fixer in the manner of Priestley (1993) for what its clamp adds.
#include "GridSampling.h"
#include "RowSampling.h"
#include "parafluid/clouds/GridSolvers.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace parafluid::clouds
{
struct AdvectionWorkspace
{
  std::vector<double> next[3];                  // the advected arrays before they are swapped in
  std::vector<double> forward[3], lo[3], hi[3]; // the plain steps and the ranges they blended
  std::vector<double> drawn;                    // the conservative step's
  struct Scalar                                 // the conservative step's per field
  {
    std::vector<double> scaled, low, high;
  } scalar[2];
  std::vector<float> move; // each cell's displacement over the step [cells]
  std::vector<std::size_t> undrawn;
};

using detail::DirectSampler;
using detail::locate;
using detail::readRow;
using detail::RowLayout;
using detail::RowVelocity;
using detail::Trilinear;
using detail::velocityAt;

namespace
{
// Sample (i, j, k) of `a` in cell units.
inline void pointOf(const GridArray& a, int i, int j, int k, double p[3])
{
  p[0] = i + a.offset[0];
  p[1] = j + a.offset[1];
  p[2] = k + a.offset[2];
}

// A thread's row buffers: the trace ends of a row's samples (x, y, z in cell units), two rows of
// values and two ranges.
struct Rows
{
  explicit Rows(int n)
    : storage(9 * static_cast<std::size_t>(n))
    , x(storage.data())
    , y(x + n)
    , z(y + n)
    , values(z + n)
    , values2(values + n)
    , lo(values2 + n)
    , hi(lo + n)
    , lo2(hi + n)
    , hi2(lo2 + n)
  {
  }
  std::vector<double> storage;
  double *x, *y, *z, *values, *values2, *lo, *hi, *lo2, *hi2;
};

// Calls body(j, k, rows) for the rows (j, k), j < rowsY, k < rowsZ, side by side on the threads,
// each thread with its own buffers for rows of up to `length` samples.
template<class Body>
void forEachRowIn(int rowsY, int rowsZ, int length, Body body)
{
#pragma omp parallel
  {
    Rows rows(length);
#pragma omp for schedule(static)
    for (int k = 0; k < rowsZ; ++k)
    {
      for (int j = 0; j < rowsY; ++j)
      {
        body(j, k, rows);
      }
    }
  }
}

// Calls body(j, k, row, rows) for every row of `layout` (row: the index of its first sample).
template<class Body>
void forEachRow(const GridArray& layout, Body body)
{
  forEachRowIn(layout.dims[1], layout.dims[2], layout.dims[0],
               [&](int j, int k, Rows& rows) { body(j, k, layout.index(0, j, k), rows); });
}

// rows.x, .y, .z = the samples of row (j, k) moved by `scale` times the grid's velocity there
// (cell units; scale = -dt / h traces back).
void traceWithVelocity(const RowVelocity& velocity, const GridArray& layout, int j, int k, double scale, Rows& r)
{
  double* const v[3] = { r.x, r.y, r.z };
  velocity.row(j, k, v);
  const double px = layout.offset[0], py = j + layout.offset[1], pz = k + layout.offset[2];
  for (int i = 0; i < layout.dims[0]; ++i)
  {
    r.x[i] = i + px + scale * r.x[i];
    r.y[i] = py + scale * r.y[i];
    r.z[i] = pz + scale * r.z[i];
  }
}

// rows.x, .y, .z = the samples of row (j, k) (first index `row`) moved by `sign` times their
// displacement over the step (`move`, cells).
void traceWithMove(const GridArray& layout, const float* move, std::size_t row, int j, int k, double sign, Rows& r)
{
  const float* m = move + 3 * row;
  const double px = layout.offset[0], py = j + layout.offset[1], pz = k + layout.offset[2];
  for (int i = 0; i < layout.dims[0]; ++i)
  {
    r.x[i] = i + px + sign * m[3 * i];
    r.y[i] = py + sign * m[3 * i + 1];
    r.z[i] = pz + sign * m[3 * i + 2];
  }
}

// Reads `data` (laid out as `sampler`'s array) at p, with `ambient` beyond the open faces; with
// lo and hi, also the range of what it blended.
inline double readAt(const DirectSampler& sampler, const GridArray& layout, const double* data, const double p[3],
                     const bool* open, double ambient, double* lo = nullptr, double* hi = nullptr)
{
  if (!sampler.beyond(p, open))
  {
    return sampler.at(data, p, lo, hi);
  }
  const Trilinear t = locate(layout, p, open);
  if (lo)
  {
    t.range(data, *lo, *hi);
    *lo = std::min(*lo, ambient);
    *hi = std::max(*hi, ambient);
  }
  return t.apply(data) + t.outside * ambient;
}

// Whether a trace end of the row may lie beyond an open face (by its extremes along each axis
// with an open face; most rows are far from them).
bool rowReachesOpenFace(const GridArray& layout, const Rows& r, const bool* open)
{
  const double* coordinates[3] = { r.x, r.y, r.z };
  const int count = layout.dims[0];
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!open[2 * axis] && !open[2 * axis + 1])
    {
      continue;
    }
    const double* c = coordinates[axis];
    double least = c[0], greatest = c[0];
#pragma omp simd reduction(min : least) reduction(max : greatest)
    for (int i = 0; i < count; ++i)
    {
      least = std::min(least, c[i]);
      greatest = std::max(greatest, c[i]);
    }
    if ((open[2 * axis] && least - layout.offset[axis] < 0.0) ||
        (open[2 * axis + 1] && greatest - layout.offset[axis] > layout.dims[axis] - 1))
    {
      return true;
    }
  }
  return false;
}

// out[i] (and the ranges lo, hi when given) = `data` at the row's trace ends: the vectorised read
// for all, then the general one for the few beyond an open face, where the ambient weighs in.
void readTraced(const GridArray& layout, const DirectSampler& sampler, const double* data, const Rows& r,
                const bool* open, double ambient, double* out, double* lo = nullptr, double* hi = nullptr)
{
  const int count = layout.dims[0];
  readRow(RowLayout(layout), data, r.x, r.y, r.z, count, out, lo, hi);
  if (!open || !rowReachesOpenFace(layout, r, open))
  {
    return;
  }
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { r.x[i], r.y[i], r.z[i] };
    if (sampler.beyond(p, open))
    {
      out[i] = readAt(sampler, layout, data, p, open, ambient, lo ? lo + i : nullptr, hi ? hi + i : nullptr);
    }
  }
}

// The same for two arrays at once: out from `data` (ambient `ambient`), out2 (and its range lo2,
// hi2 when given) from `data2` (ambient `ambient2`).
void readTracedPair(const GridArray& layout, const DirectSampler& sampler, const double* data, const double* data2,
                    const Rows& r, const bool* open, double* out, double* out2, double* lo2, double* hi2,
                    double ambient = 0.0, double ambient2 = 0.0)
{
  const int count = layout.dims[0];
  detail::readRowPair(RowLayout(layout), data, data2, r.x, r.y, r.z, count, out, out2, lo2, hi2);
  if (!open || !rowReachesOpenFace(layout, r, open))
  {
    return;
  }
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { r.x[i], r.y[i], r.z[i] };
    if (sampler.beyond(p, open))
    {
      out[i] = readAt(sampler, layout, data, p, open, ambient);
      out2[i] = readAt(sampler, layout, data2, p, open, ambient2, lo2 ? lo2 + i : nullptr, hi2 ? hi2 + i : nullptr);
    }
  }
}

// out, out2 = `data`, `data2` (ambient 0) at the row's trace ends, and in r.lo, r.hi (r.lo2,
// r.hi2) the range of `range` (`range2`, ambients `ambient`, `ambient2` beyond open faces) that
// a read there blends.
void readTracedPairRanged(const GridArray& layout, const DirectSampler& sampler, const double* data,
                          const double* data2, const double* range, const double* range2, double ambient,
                          double ambient2, const Rows& r, const bool* open, double* out, double* out2)
{
  const int count = layout.dims[0];
  detail::readRowPairRanged(RowLayout(layout), data, data2, range, range2, r.x, r.y, r.z, count, out, out2, r.lo, r.hi,
                            r.lo2, r.hi2);
  if (!open || !rowReachesOpenFace(layout, r, open))
  {
    return;
  }
  for (int i = 0; i < count; ++i)
  {
    const double p[3] = { r.x[i], r.y[i], r.z[i] };
    if (sampler.beyond(p, open))
    {
      out[i] = readAt(sampler, layout, data, p, open, 0.0);
      out2[i] = readAt(sampler, layout, data2, p, open, 0.0);
      readAt(sampler, layout, range, p, open, ambient, r.lo + i, r.hi + i);
      readAt(sampler, layout, range2, p, open, ambient2, r.lo2 + i, r.hi2 + i);
    }
  }
}

// Calls f(index, weight) for the samples of `layout` a read at p blends (open faces: those
// inside the box only; the rest of the weight is the ambient's).
template<class F>
inline void forCornersAt(const DirectSampler& sampler, const GridArray& layout, const double p[3], const bool* open,
                         F&& f)
{
  if (!sampler.beyond(p, open))
  {
    sampler.forCorners(p, f);
    return;
  }
  const Trilinear t = locate(layout, p, open);
  for (int c = 0; c < 8; ++c)
  {
    if (t.weight[c] > 0.0)
    {
      f(t.index[c], t.weight[c]);
    }
  }
}

// One semi-Lagrangian step of `field` (ambient `ambient` beyond the open faces `open`, when
// given): each sample traced back by the velocity at the sample (dt * v / h cells) and read
// there. With MacCormack, that result traced forward again the same way, half the round trip's
// error added back, clamped to the range the backward read blended. The forward Euler trace is
// enough here: the round trip measures its error together with the interpolation's, and the
// correction removes both to second order in smooth flow.
class Carried
{
public:
  /// `field` carried into `out`; `slot` picks the workspace's arrays for the MacCormack step.
  Carried(const GridArray& field, const StaggeredGrid& g, double dt, bool macCormack, const bool* open, double ambient,
          AdvectionWorkspace& work, int slot, std::vector<double>& out)
    : Field(field)
    , Velocity(g, field)
    , Sampler(field)
    , Step(dt / g.h)
    , MacCormack(macCormack)
    , Open(open)
    , Ambient(ambient)
    , Forward(work.forward[slot])
    , Low(work.lo[slot])
    , High(work.hi[slot])
    , Out(out)
  {
    const std::size_t n = field.values.size();
    out.resize(n);
    if (macCormack)
    {
      Forward.resize(n);
      Low.resize(n);
      High.resize(n);
    }
  }
  bool hasRow(int j, int k) const { return j < Field.dims[1] && k < Field.dims[2]; }
  /// The plain step of row (j, k): traced back and read there (with MacCormack, into the forward
  /// array, with the range it blended).
  void back(int j, int k, Rows& r) const
  {
    const std::size_t row = Field.index(0, j, k);
    traceWithVelocity(Velocity, Field, j, k, -Step, r);
    std::vector<double>& plain = MacCormack ? Forward : Out;
    readTraced(Field, Sampler, Field.values.data(), r, Open, Ambient, plain.data() + row,
               MacCormack ? Low.data() + row : nullptr, MacCormack ? High.data() + row : nullptr);
  }
  /// The MacCormack correction of row (j, k), once every row has had back().
  void correct(int j, int k, Rows& r) const
  {
    const std::size_t row = Field.index(0, j, k);
    traceWithVelocity(Velocity, Field, j, k, Step, r);
    readTraced(Field, Sampler, Forward.data(), r, Open, Ambient, r.values);
    const double* source = Field.values.data();
    for (int i = 0; i < Field.dims[0]; ++i)
    {
      const std::size_t id = row + i;
      const double corrected = Forward[id] + 0.5 * (source[id] - r.values[i]);
      Out[id] = std::clamp(corrected, Low[id], High[id]);
    }
  }
  const GridArray& field() const { return Field; }

private:
  const GridArray& Field;
  const RowVelocity Velocity;
  const DirectSampler Sampler;
  const double Step; // dt / h
  const bool MacCormack;
  const bool* Open;
  const double Ambient;
  std::vector<double>&Forward, &Low, &High, &Out;
};

void advectOne(const GridArray& field, const StaggeredGrid& g, double dt, bool macCormack, const bool* open,
               double ambient, AdvectionWorkspace& work, std::vector<double>& out)
{
  const Carried carried(field, g, dt, macCormack, open, ambient, work, 0, out);
  forEachRow(field, [&](int j, int k, std::size_t, Rows& r) { carried.back(j, k, r); });
  if (macCormack)
  {
    forEachRow(field, [&](int j, int k, std::size_t, Rows& r) { carried.correct(j, k, r); });
  }
}
} // namespace

std::shared_ptr<AdvectionWorkspace> makeAdvectionWorkspace()
{
  return std::make_shared<AdvectionWorkspace>();
}

GridArray advect(const GridArray& field, const StaggeredGrid& grid, double dt, bool macCormack)
{
  AdvectionWorkspace work;
  GridArray result;
  result.dims = field.dims;
  result.offset = field.offset;
  advectOne(field, grid, dt, macCormack, nullptr, 0.0, work, result.values);
  return result;
}

void advectVelocity(StaggeredGrid& g, double dt, bool macCormack, AdvectionWorkspace* workspace)
{
  AdvectionWorkspace local;
  AdvectionWorkspace& work = workspace ? *workspace : local;
  // All three components carried by the old velocity, then swapped in (the old values' storage
  // is the next step's). The three run in one pass over the rows: the neighbourhood of a row,
  // which the velocity and the traces read, is then read once for all three instead of thrice.
  GridArray* faces[3] = { &g.u, &g.v, &g.w };
  const Carried carried[3] = { { g.u, g, dt, macCormack, nullptr, 0.0, work, 0, work.next[0] },
                               { g.v, g, dt, macCormack, nullptr, 0.0, work, 1, work.next[1] },
                               { g.w, g, dt, macCormack, nullptr, 0.0, work, 2, work.next[2] } };
  auto allRows = [&](auto&& each)
  {
    forEachRowIn(g.ny + 1, g.nz + 1, g.nx + 1,
                 [&](int j, int k, Rows& r)
                 {
                   for (const Carried& c : carried)
                   {
                     if (c.hasRow(j, k))
                       each(c, j, k, r);
                   }
                 });
  };
  allRows([](const Carried& c, int j, int k, Rows& r) { c.back(j, k, r); });
  if (macCormack)
  {
    allRows([](const Carried& c, int j, int k, Rows& r) { c.correct(j, k, r); });
  }
  for (int c = 0; c < 3; ++c)
  {
    std::swap(faces[c]->values, work.next[c]);
  }
}

void advectScalars(const StaggeredGrid& g, const std::vector<ScalarField>& fields, double dt, bool sharpen,
                   bool conservative, AdvectionWorkspace* workspace)
{
  AdvectionWorkspace local;
  AdvectionWorkspace& work = workspace ? *workspace : local;
  const bool* open = g.anyOpen() ? g.open.data() : nullptr;
  if (!conservative)
  {
    std::size_t next = 0;
    if (!sharpen)
    {
      // Plain tracing: two fields at a time share each trace and its corners.
      const double s = dt / g.h;
      const RowVelocity velocity(g, g.density);
      const DirectSampler sampler(g.density);
      for (; next + 1 < fields.size(); next += 2)
      {
        const ScalarField &a = fields[next], &b = fields[next + 1];
        work.next[0].resize(a.field->values.size());
        work.next[1].resize(b.field->values.size());
        forEachRow(g.density,
                   [&](int j, int k, std::size_t row, Rows& r)
                   {
                     traceWithVelocity(velocity, g.density, j, k, -s, r);
                     readTracedPair(g.density, sampler, a.field->values.data(), b.field->values.data(), r, open,
                                    work.next[0].data() + row, work.next[1].data() + row, nullptr, nullptr, a.ambient,
                                    b.ambient);
                   });
        std::swap(a.field->values, work.next[0]);
        std::swap(b.field->values, work.next[1]);
      }
    }
    for (; next < fields.size(); ++next)
    {
      const ScalarField& f = fields[next];
      advectOne(*f.field, g, dt, sharpen, open, f.ambient, work, work.next[0]);
      std::swap(f.field->values, work.next[0]);
    }
    return;
  }
  const GridArray& layout = g.density;
  const std::size_t n = g.cells();
  const double s = dt / g.h;
  const DirectSampler sampler(layout);
  // 1. Each cell's displacement over the step [cells] (its trace starts at p - move).
  std::vector<float>& move = work.move;
  move.resize(3 * n);
  double fastest = 0.0;
  for (const GridArray* f : { &g.u, &g.v, &g.w })
  {
    const double* values = f->values.data();
    const long long count = static_cast<long long>(f->values.size());
#pragma omp parallel for schedule(static) reduction(max : fastest)
    for (long long c = 0; c < count; ++c)
    {
      fastest = std::max(fastest, std::abs(values[c]));
    }
  }
  const RowVelocity velocity(g, layout);
  forEachRow(layout,
             [&](int j, int k, std::size_t row, Rows& r)
             {
               double* const v[3] = { r.x, r.y, r.z };
               velocity.row(j, k, v);
               for (int i = 0; i < layout.dims[0]; ++i)
               {
                 for (int c = 0; c < 3; ++c)
                 {
                   move[3 * (row + i) + c] = static_cast<float>(s * v[c][i]);
                 }
               }
             });
  // 2. How much of each source cell the traces draw in all ("drawn"). A trace reaches at most
  // `reach` slabs from its cell, so slabs in blocks more than twice that apart never write the
  // same source: the even blocks run side by side, then the odd ones (no atomics).
  std::vector<double>& drawn = work.drawn;
  drawn.assign(n, 0.0);
  const int reach = static_cast<int>(std::ceil(s * fastest)) + 1;
  const int block = 2 * reach + 1;
  const int nz = layout.dims[2];
  const int blocks = (nz + block - 1) / block;
  for (int phase = 0; phase < 2; ++phase)
  {
#pragma omp parallel
    {
      Rows r(layout.dims[0]);
      std::vector<int> corners(layout.dims[0]);
#pragma omp for schedule(dynamic)
      for (int b = phase; b < blocks; b += 2)
      {
        for (int k = b * block; k < std::min((b + 1) * block, nz); ++k)
        {
          for (int j = 0; j < layout.dims[1]; ++j)
          {
            traceWithMove(layout, move.data(), layout.index(0, j, k), j, k, -1.0, r);
            if (!open || !rowReachesOpenFace(layout, r, open))
            {
              // The row's corners and fractions in vectors, then the adds.
              detail::scatterRow(RowLayout(layout), r.x, r.y, r.z, layout.dims[0], corners.data(), r.values, r.values2,
                                 r.lo, drawn.data());
              continue;
            }
            for (int i = 0; i < layout.dims[0]; ++i)
            {
              const double back[3] = { r.x[i], r.y[i], r.z[i] };
              forCornersAt(sampler, layout, back, open,
                           [&](std::size_t index, double weight) { drawn[index] += weight; });
            }
          }
        }
      }
    }
  }
  if (open)
  {
    // Beyond the open faces, virtual cells (as many layers as the flow moves in a step) draw
    // from the box too: what they draw is what flows out.
    const int layers = static_cast<int>(std::ceil(s * fastest)) + 2;
    int lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      lo[axis] = g.open[2 * axis] ? -layers : 0;
      hi[axis] = layout.dims[axis] + (g.open[2 * axis + 1] ? layers : 0);
    }
#pragma omp parallel for schedule(dynamic)
    for (int k = lo[2]; k < hi[2]; ++k)
    {
      for (int j = lo[1]; j < hi[1]; ++j)
      {
        for (int i = lo[0]; i < hi[0]; ++i)
        {
          if (i >= 0 && j >= 0 && k >= 0 && i < layout.dims[0] && j < layout.dims[1] && k < layout.dims[2])
          {
            continue;
          }
          double p[3], v[3];
          pointOf(layout, i, j, k, p);
          velocityAt(g, p, v); // the velocity continues past the face
          const double from[3] = { p[0] - s * v[0], p[1] - s * v[1], p[2] - s * v[2] };
          const Trilinear t = locate(layout, from, open);
          for (int c = 0; c < 8; ++c)
          {
            if (t.weight[c] > 0.0)
            {
#pragma omp atomic
              drawn[t.index[c]] += t.weight[c];
            }
          }
        }
      }
    }
  }
  // Cells no trace draws from (where the flow diverges) give their content forward instead.
  std::vector<std::size_t>& undrawn = work.undrawn;
  undrawn.clear();
  for (std::size_t id = 0; id < n; ++id)
  {
    if (drawn[id] <= 0.0)
    {
      undrawn.push_back(id);
    }
  }
  // The cells no trace draws from give `content` forward, along their own displacement.
  auto pushForward = [&](const std::vector<double>& content, std::vector<double>& out)
  {
    for (std::size_t id : undrawn)
    {
      const int i = static_cast<int>(id % layout.dims[0]);
      const int j = static_cast<int>((id / layout.dims[0]) % layout.dims[1]);
      const int k = static_cast<int>(id / (static_cast<std::size_t>(layout.dims[0]) * layout.dims[1]));
      double p[3];
      pointOf(layout, i, j, k, p);
      const double ahead[3] = { p[0] + move[3 * id], p[1] + move[3 * id + 1], p[2] + move[3 * id + 2] };
      forCornersAt(sampler, layout, ahead, open,
                   [&](std::size_t index, double weight) { out[index] += weight * content[id]; });
    }
  };
  // The fields go two at a time (density and temperature): they share each trace and the
  // corners it reads. (A lone field runs as a pair with itself; only its own result is kept.)
  // Each field's excess over ambient is e = value - ambient. A cell that no trace draws from
  // holds in `scaled` its content itself instead of content / drawn: no read weighs it, and
  // pushForward gives it forward from there.
  for (std::size_t first = 0; first < fields.size(); first += 2)
  {
    const int m = fields.size() - first >= 2 ? 2 : 1;
    const ScalarField* group[2] = { &fields[first], &fields[first + m - 1] };
    AdvectionWorkspace::Scalar* w[2] = { &work.scalar[0], &work.scalar[1] };
    const double* values[2] = { group[0]->field->values.data(), group[1]->field->values.data() };
    const double ambient[2] = { group[0]->ambient, group[1]->ambient };
    for (int f = 0; f < 2; ++f)
    {
      w[f]->scaled.resize(n);
      w[f]->low.resize(n);
      w[f]->high.resize(sharpen ? n : 0);
    }
    // 3. Low order and conservative: each source cell's excess shared out exactly among the
    // cells that draw from it, in proportion to their weights.
    for (int f = 0; f < 2; ++f)
    {
      const double* value = values[f];
      const double air = ambient[f];
      double* scaled = w[f]->scaled.data();
#pragma omp parallel for schedule(static)
      for (long long id = 0; id < static_cast<long long>(n); ++id)
      {
        const double e = value[id] - air;
        scaled[id] = drawn[id] > 0.0 ? e / drawn[id] : e;
      }
    }
    forEachRow(layout,
               [&](int j, int k, std::size_t row, Rows& r)
               {
                 traceWithMove(layout, move.data(), row, j, k, -1.0, r);
                 readTracedPair(layout, sampler, w[0]->scaled.data(), w[1]->scaled.data(), r, open,
                                w[0]->low.data() + row, w[1]->low.data() + row, nullptr, nullptr);
               });
    for (int f = 0; f < m; ++f)
    {
      pushForward(w[f]->scaled, w[f]->low);
    }
    if (!sharpen)
    {
      for (int f = 0; f < m; ++f)
      {
        double* value = group[f]->field->values.data();
        const double* low = w[f]->low.data();
        const double air = ambient[f];
#pragma omp parallel for schedule(static)
        for (long long id = 0; id < static_cast<long long>(n); ++id)
        {
          value[id] = low[id] + air;
        }
      }
      continue;
    }
    // 4. High order: BFECC (Kim et al. 2005) with the conservative step: the error of a round
    // trip (forward conservatively, back plainly) taken out of the field first (into `scaled`,
    // whose low-order use is over), then the conservative step again, clamped to the range of
    // the excess the trace blends.
    forEachRow(layout,
               [&](int j, int k, std::size_t row, Rows& r)
               {
                 traceWithMove(layout, move.data(), row, j, k, 1.0, r);
                 readTracedPair(layout, sampler, w[0]->low.data(), w[1]->low.data(), r, open, r.values, r.values2,
                                nullptr, nullptr);
                 const double* roundTrip[2] = { r.values, r.values2 };
                 const double* weight = drawn.data() + row;
                 for (int f = 0; f < 2; ++f)
                 {
                   const double* value = values[f] + row;
                   const double air = ambient[f];
                   double* scaled = w[f]->scaled.data() + row;
                   for (int i = 0; i < layout.dims[0]; ++i)
                   {
                     const double e = value[i] - air;
                     const double forward = e + 0.5 * (e - roundTrip[f][i]);
                     scaled[i] = weight[i] > 0.0 ? forward / weight[i] : forward;
                   }
                 }
               });
    forEachRow(layout,
               [&](int j, int k, std::size_t row, Rows& r)
               {
                 traceWithMove(layout, move.data(), row, j, k, -1.0, r);
                 double* high[2] = { w[0]->high.data() + row, w[1]->high.data() + row };
                 readTracedPairRanged(layout, sampler, w[0]->scaled.data(), w[1]->scaled.data(), values[0], values[1],
                                      ambient[0], ambient[1], r, open, high[0], high[1]);
                 const double* lo[2] = { r.lo, r.lo2 };
                 const double* hi[2] = { r.hi, r.hi2 };
                 for (int f = 0; f < 2; ++f)
                 {
                   const double air = ambient[f];
                   for (int i = 0; i < layout.dims[0]; ++i)
                   {
                     high[f][i] = std::clamp(high[f][i], lo[f][i] - air, hi[f][i] - air);
                   }
                 }
               });
    for (int f = 0; f < m; ++f)
    {
      pushForward(w[f]->scaled, w[f]->high);
      // 5. The mass fixer: the clamp's surplus (or deficit) against the conservative result is
      // taken back from the cells whose correction carries it, in proportion to that correction;
      // every cell stays between its low- and high-order values.
      const double* high = w[f]->high.data();
      const double* low = w[f]->low.data();
      double surplus = 0.0, positive = 0.0, negative = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : surplus, positive, negative)
      for (long long id = 0; id < static_cast<long long>(n); ++id)
      {
        const double d = high[id] - low[id];
        surplus += d;
        positive += std::max(d, 0.0);
        negative += std::min(d, 0.0);
      }
      double keepPositive = 1.0, keepNegative = 1.0;
      if (surplus > 0.0 && positive > 0.0)
      {
        keepPositive = std::clamp(-negative / positive, 0.0, 1.0);
      }
      else if (surplus < 0.0 && negative < 0.0)
      {
        keepNegative = std::clamp(-positive / negative, 0.0, 1.0);
      }
      double* value = group[f]->field->values.data();
      const double air = ambient[f];
#pragma omp parallel for schedule(static)
      for (long long id = 0; id < static_cast<long long>(n); ++id)
      {
        const double d = high[id] - low[id];
        value[id] = air + low[id] + d * (d > 0.0 ? keepPositive : keepNegative);
      }
    }
  }
}
} // namespace parafluid::clouds
