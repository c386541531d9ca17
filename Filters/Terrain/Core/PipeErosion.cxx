#include "parafluid/terrain/PipeErosion.h"

#include "parafluid/terrain/TerrainParameterTables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::terrain
{
std::string PipeSettings::problem() const
{
  return checkDeclared(pipeParameterTable(), *this);
}

// Layout: every field has a ring of ghost cells around the grid (row stride nx + 2), so a cell's
// four neighbours are always inside the array and the loops below have no branches on the grid's
// edges (they vectorise). Ghost cells are never written: their water, sediment and fluxes stay 0,
// so nothing flows in from outside; flows out through an edge and the edge's tilt are masked
// with selects on the index.
PipeErosion::PipeErosion(const ElevationGrid& terrain, const PipeSettings& settings)
  : Settings(settings)
  , NX(terrain.nx)
  , NY(terrain.ny)
  , LX(static_cast<float>(terrain.dx))
  , LY(static_cast<float>(terrain.dy))
{
  std::string problem = settings.problem();
  if (problem.empty())
  {
    problem = terrain.problem();
  }
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const std::size_t padded = static_cast<std::size_t>(this->NX + 2) * static_cast<std::size_t>(this->NY + 2);
  for (auto* field : { &this->B, &this->D, &this->S, &this->S2, &this->FL, &this->FR, &this->FB, &this->FT, &this->Q,
                       &this->Delta, &this->Eroded, &this->Deposited, &this->Outflow })
  {
    field->assign(padded, 0.0f);
  }
  for (int j = 0; j < this->NY; ++j)
  {
    for (int i = 0; i < this->NX; ++i)
    {
      this->B[this->cell(i, j)] = terrain.at(i, j);
    }
  }
}

std::vector<float> PipeErosion::unpadded(const std::vector<float>& field) const
{
  std::vector<float> values(static_cast<std::size_t>(this->NX) * static_cast<std::size_t>(this->NY));
  for (int j = 0; j < this->NY; ++j)
  {
    std::copy_n(field.begin() + static_cast<std::ptrdiff_t>(this->cell(0, j)), this->NX,
                values.begin() + static_cast<std::ptrdiff_t>(j) * this->NX);
  }
  return values;
}

void PipeErosion::step()
{
  this->computeFluxes();
  this->updateWaterAndErode();
  this->transportSediment();
  ++this->Steps;
}

namespace
{
// One row of each pass. The row's fields come in as restrict parameters (GCC honours restrict on
// parameters, not on local pointers), so the loops vectorise without run-time alias checks.
// "below"/"above" are the same fields one row down/up; they are only read.

struct FluxConstants
{
  float kx, ky, dt, area, rain;
  bool bottomOpen, topOpen;
};

void fluxRow(int nx, const FluxConstants c, const float* __restrict b, const float* __restrict bBelow,
             const float* __restrict bAbove, const float* __restrict d, const float* __restrict dBelow,
             const float* __restrict dAbove, float* __restrict fL, float* __restrict fR, float* __restrict fB,
             float* __restrict fT, float* __restrict q)
{
  for (int i = 0; i < nx; ++i)
  {
    const float h = b[i] + d[i];
    const float l = std::max(0.0f, fL[i] + c.kx * (h - b[i - 1] - d[i - 1]));
    const float r = std::max(0.0f, fR[i] + c.kx * (h - b[i + 1] - d[i + 1]));
    const float down = std::max(0.0f, fB[i] + c.ky * (h - bBelow[i] - dBelow[i]));
    const float up = std::max(0.0f, fT[i] + c.ky * (h - bAbove[i] - dAbove[i]));
    // Walls: nothing flows out through the grid's edges.
    const float fl = i > 0 ? l : 0.0f, fr = i < nx - 1 ? r : 0.0f;
    const float fb = c.bottomOpen ? down : 0.0f, ft = c.topOpen ? up : 0.0f;
    const float water = (d[i] + c.rain) * c.area;
    const float out = (fl + fr + fb + ft) * c.dt;
    // No cell gives more water than it holds (out > water implies out > 0).
    const float scale = out > water ? water / out : 1.0f;
    fL[i] = fl * scale, fR[i] = fr * scale, fB[i] = fb * scale, fT[i] = ft * scale;
    // The fraction of the cell's water (and sediment) one unit of flux takes in a step.
    q[i] = water > 1e-12f ? c.dt / water : 0.0f;
  }
}

struct WaterConstants
{
  float dt, area, rain, dissolve, deposit, evaporate, inverseCapacityDepth, invLX, invLY, dyScale, capacity, minTilt;
};

void waterRow(int nx, const WaterConstants c, const float* __restrict b, const float* __restrict bBelow,
              const float* __restrict bAbove, const float* __restrict s, const float* __restrict fL,
              const float* __restrict fR, const float* __restrict fB, const float* __restrict fT,
              const float* __restrict fTBelow, const float* __restrict fBAbove, float* __restrict d,
              float* __restrict delta, float* __restrict outflow)
{
  for (int i = 0; i < nx; ++i)
  {
    // Ghost fluxes are 0: nothing comes in from outside the grid.
    const float inLeft = fR[i - 1], inRight = fL[i + 1], inBottom = fTBelow[i], inTop = fBAbove[i];
    const float out = fL[i] + fR[i] + fB[i] + fT[i];
    const float d1 = d[i] + c.rain;
    const float d2 = std::max(0.0f, d1 + c.dt * (inLeft + inRight + inBottom + inTop - out) / c.area);
    const float mean = 0.5f * (d1 + d2);
    const float u = 0.5f * (inLeft - fL[i] + fR[i] - inRight) * c.invLY;
    const float v = 0.5f * (inBottom - fB[i] + fT[i] - inTop) * c.invLX;
    const float speed = mean > 1e-6f ? std::sqrt(u * u + v * v) / mean : 0.0f;
    // Tilt from central differences, one-sided on the edges (the ghost values are not used).
    const float here = b[i], east = b[i + 1], west = b[i - 1];
    const float right = i < nx - 1 ? east : here, left = i > 0 ? west : here;
    const float dxScale = (i > 0 && i < nx - 1) ? 0.5f * c.invLX : c.invLX;
    const float gx = (right - left) * dxScale;
    const float gy = (bAbove[i] - bBelow[i]) * c.dyScale;
    const float slope2 = gx * gx + gy * gy;
    const float sinTilt = std::sqrt(slope2 / (1.0f + slope2));
    const float capacity =
      c.capacity * std::max(sinTilt, c.minTilt) * speed * std::min(1.0f, d2 * c.inverseCapacityDepth);
    // Delta > 0: ground dissolved into the water; < 0: sediment laid down.
    delta[i] = capacity > s[i] ? c.dissolve * (capacity - s[i]) : -c.deposit * (s[i] - capacity);
    d[i] = d2 * c.evaporate;
    outflow[i] += out * c.dt;
  }
}

void sedimentRow(int nx, const float* __restrict s, const float* __restrict sBelow, const float* __restrict sAbove,
                 const float* __restrict delta, const float* __restrict deltaBelow, const float* __restrict deltaAbove,
                 const float* __restrict fL, const float* __restrict fR, const float* __restrict fB,
                 const float* __restrict fT, const float* __restrict fTBelow, const float* __restrict fBAbove,
                 const float* __restrict q, const float* __restrict qBelow, const float* __restrict qAbove,
                 float* __restrict b, float* __restrict eroded, float* __restrict deposited, float* __restrict next)
{
  for (int i = 0; i < nx; ++i)
  {
    const float change = delta[i];
    b[i] -= change;
    eroded[i] += std::max(change, 0.0f);
    deposited[i] += std::max(-change, 0.0f);
    // Suspended sediment after erosion, of this cell and (read, not written) of its neighbours;
    // ghosts hold no sediment and no flux.
    const float leaving = (fL[i] + fR[i] + fB[i] + fT[i]) * q[i];
    next[i] = (s[i] + change) * (1.0f - leaving) + (s[i - 1] + delta[i - 1]) * fR[i - 1] * q[i - 1] +
              (s[i + 1] + delta[i + 1]) * fL[i + 1] * q[i + 1] + (sBelow[i] + deltaBelow[i]) * fTBelow[i] * qBelow[i] +
              (sAbove[i] + deltaAbove[i]) * fBAbove[i] * qAbove[i];
  }
}
} // namespace

void PipeErosion::computeFluxes()
{
  const int nx = this->NX, ny = this->NY;
  const std::ptrdiff_t stride = nx + 2;
  const float dt = this->Settings.timeStep;
  // Pipe cross-section l^2: f += dt g dh l (per pipe of length l); rain is uniform, so it leaves
  // the differences of surface height alone and enters only the cell's own water.
  FluxConstants c{ dt * this->Settings.gravity * this->LY,
                   dt * this->Settings.gravity * this->LX,
                   dt,
                   this->LX * this->LY,
                   this->Settings.rainRate * dt,
                   false,
                   false };
#pragma omp parallel for schedule(static) firstprivate(c)
  for (int j = 0; j < ny; ++j)
  {
    const std::size_t k = this->cell(0, j);
    c.bottomOpen = j > 0, c.topOpen = j < ny - 1;
    const float *b = this->B.data() + k, *d = this->D.data() + k;
    fluxRow(nx, c, b, b - stride, b + stride, d, d - stride, d + stride, this->FL.data() + k, this->FR.data() + k,
            this->FB.data() + k, this->FT.data() + k, this->Q.data() + k);
  }
}

void PipeErosion::updateWaterAndErode()
{
  const int nx = this->NX, ny = this->NY;
  const std::ptrdiff_t stride = nx + 2;
  const PipeSettings& p = this->Settings;
  const float dt = p.timeStep;
  WaterConstants c{ dt,
                    this->LX * this->LY,
                    p.rainRate * dt,
                    std::min(1.0f, p.dissolveRate * dt),
                    std::min(1.0f, p.depositRate * dt),
                    std::max(0.0f, 1.0f - p.evaporation * dt),
                    1.0f / p.capacityDepth,
                    1.0f / this->LX,
                    1.0f / this->LY,
                    0.0f,
                    p.capacity,
                    p.minTilt };
#pragma omp parallel for schedule(static) firstprivate(c)
  for (int j = 0; j < ny; ++j)
  {
    const std::size_t k = this->cell(0, j);
    c.dyScale = 1.0f / (this->LY * static_cast<float>((j > 0) + (j < ny - 1)));
    const float* b = this->B.data() + k;
    const float* fB = this->FB.data() + k;
    const float* fT = this->FT.data() + k;
    waterRow(nx, c, b, b + (j > 0 ? -stride : 0), b + (j < ny - 1 ? stride : 0), this->S.data() + k,
             this->FL.data() + k, this->FR.data() + k, fB, fT, fT - stride, fB + stride, this->D.data() + k,
             this->Delta.data() + k, this->Outflow.data() + k);
  }
}

void PipeErosion::transportSediment()
{
  const int nx = this->NX, ny = this->NY;
  const std::ptrdiff_t stride = nx + 2;
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny; ++j)
  {
    const std::size_t k = this->cell(0, j);
    const float *s = this->S.data() + k, *delta = this->Delta.data() + k, *q = this->Q.data() + k;
    const float *fB = this->FB.data() + k, *fT = this->FT.data() + k;
    sedimentRow(nx, s, s - stride, s + stride, delta, delta - stride, delta + stride, this->FL.data() + k,
                this->FR.data() + k, fB, fT, fT - stride, fB + stride, q, q - stride, q + stride, this->B.data() + k,
                this->Eroded.data() + k, this->Deposited.data() + k, this->S2.data() + k);
  }
  this->S.swap(this->S2);
}

ErosionMaps PipeErosion::maps() const
{
  ErosionMaps m;
  m.waterFlow = this->unpadded(this->Outflow);
  const float time = this->Steps > 0 ? this->Settings.timeStep * static_cast<float>(this->Steps) : 1.0f;
  for (float& f : m.waterFlow)
  {
    f /= time;
  }
  m.sedimentDeposited = this->unpadded(this->Deposited);
  m.erodedDepth = this->unpadded(this->Eroded);
  return m;
}

SedimentBudget PipeErosion::budget() const
{
  // Summed from the per-cell maps (the totals are only wanted at the end).
  double eroded = 0.0, deposited = 0.0, suspended = 0.0;
  for (std::size_t k = 0; k < this->S.size(); ++k)
  {
    eroded += this->Eroded[k], deposited += this->Deposited[k], suspended += this->S[k];
  }
  const double area = static_cast<double>(this->LX) * this->LY;
  SedimentBudget b;
  b.eroded = eroded * area;
  b.deposited = deposited * area;
  b.carried = suspended * area;
  return b;
}
} // namespace parafluid::terrain
