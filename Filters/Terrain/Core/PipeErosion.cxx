#include "parafluid/terrain/PipeErosion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace parafluid::terrain
{
std::string PipeSettings::problem() const
{
  const auto check = [](const char* name, float value, float lo, float hi, const char* unit) -> std::string
  {
    if (std::isfinite(value) && value >= lo && value <= hi)
    {
      return {};
    }
    return std::string(name) + " = " + std::to_string(value) + " is not allowed: it must be from " +
           std::to_string(lo) + " to " + std::to_string(hi) + unit;
  };
  for (const std::string& p :
       { check("TimeStep", timeStep, 1e-6f, 10.0f, " s"), check("RainRate", rainRate, 0.0f, 10.0f, " m/s"),
         check("Gravity", gravity, 0.0f, 1000.0f, " m/s^2"), check("SedimentCapacity", capacity, 0.0f, 1e6f, ""),
         check("DissolveRate", dissolveRate, 0.0f, 1e6f, " 1/s"),
         check("PipeDepositRate", depositRate, 0.0f, 1e6f, " 1/s"),
         check("PipeEvaporation", evaporation, 0.0f, 1e6f, " 1/s"), check("MinTilt", minTilt, 0.0f, 1.0f, ""),
         check("CapacityDepth", capacityDepth, 1e-6f, 1e6f, " m") })
  {
    if (!p.empty())
    {
      return p;
    }
  }
  return {};
}

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
  const std::size_t n = terrain.size();
  this->B = terrain.elevation;
  for (auto* field : { &this->D, &this->S, &this->S2, &this->FL, &this->FR, &this->FB, &this->FT, &this->Q,
                       &this->Delta, &this->Eroded, &this->Deposited, &this->Outflow })
  {
    field->assign(n, 0.0f);
  }
}

void PipeErosion::step()
{
  this->computeFluxes();
  this->updateWaterAndErode();
  this->transportSediment();
  ++this->Steps;
}

void PipeErosion::computeFluxes()
{
  const int nx = this->NX, ny = this->NY;
  const float dt = this->Settings.timeStep;
  const float area = this->LX * this->LY;
  // Pipe cross-section l^2: f += dt g dh l (per pipe of length l); rain is uniform, so it leaves
  // the differences of surface height alone and enters only the cell's own water.
  const float kx = dt * this->Settings.gravity * this->LY, ky = dt * this->Settings.gravity * this->LX;
  const float rain = this->Settings.rainRate * dt;
  const float* b = this->B.data();
  const float* d = this->D.data();
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      const float h = b[k] + d[k];
      float fl = i > 0 ? std::max(0.0f, this->FL[k] + kx * (h - b[k - 1] - d[k - 1])) : 0.0f;
      float fr = i < nx - 1 ? std::max(0.0f, this->FR[k] + kx * (h - b[k + 1] - d[k + 1])) : 0.0f;
      float fb = j > 0 ? std::max(0.0f, this->FB[k] + ky * (h - b[k - nx] - d[k - nx])) : 0.0f;
      float ft = j < ny - 1 ? std::max(0.0f, this->FT[k] + ky * (h - b[k + nx] - d[k + nx])) : 0.0f;
      const float water = (d[k] + rain) * area;
      const float out = (fl + fr + fb + ft) * dt;
      if (out > water)
      {
        const float scale = out > 0.0f ? water / out : 0.0f;
        fl *= scale, fr *= scale, fb *= scale, ft *= scale;
      }
      this->FL[k] = fl, this->FR[k] = fr, this->FB[k] = fb, this->FT[k] = ft;
      // The fraction of the cell's water (and sediment) one unit of flux takes in a step.
      this->Q[k] = water > 1e-12f ? dt / water : 0.0f;
    }
  }
}

void PipeErosion::updateWaterAndErode()
{
  const int nx = this->NX, ny = this->NY;
  const PipeSettings& p = this->Settings;
  const float dt = p.timeStep, area = this->LX * this->LY;
  const float rain = p.rainRate * dt;
  const float dissolve = std::min(1.0f, p.dissolveRate * dt), deposit = std::min(1.0f, p.depositRate * dt);
  const float evaporate = std::max(0.0f, 1.0f - p.evaporation * dt);
  const float inverseCapacityDepth = 1.0f / p.capacityDepth;
  const float* b = this->B.data();
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      const float inLeft = i > 0 ? this->FR[k - 1] : 0.0f, inRight = i < nx - 1 ? this->FL[k + 1] : 0.0f;
      const float inBottom = j > 0 ? this->FT[k - nx] : 0.0f, inTop = j < ny - 1 ? this->FB[k + nx] : 0.0f;
      const float out = this->FL[k] + this->FR[k] + this->FB[k] + this->FT[k];
      const float d1 = this->D[k] + rain;
      const float d2 = std::max(0.0f, d1 + dt * (inLeft + inRight + inBottom + inTop - out) / area);
      const float mean = 0.5f * (d1 + d2);
      float speed = 0.0f;
      if (mean > 1e-6f)
      {
        const float u = 0.5f * (inLeft - this->FL[k] + this->FR[k] - inRight) / (this->LY * mean);
        const float v = 0.5f * (inBottom - this->FB[k] + this->FT[k] - inTop) / (this->LX * mean);
        speed = std::sqrt(u * u + v * v);
      }
      // Tilt of the ground from central differences (one-sided at the edges).
      const float gx = (b[i < nx - 1 ? k + 1 : k] - b[i > 0 ? k - 1 : k]) / (this->LX * ((i > 0) + (i < nx - 1)));
      const float gy = (b[j < ny - 1 ? k + nx : k] - b[j > 0 ? k - nx : k]) / (this->LY * ((j > 0) + (j < ny - 1)));
      const float slope2 = gx * gx + gy * gy;
      const float sinTilt = std::sqrt(slope2 / (1.0f + slope2));
      const float capacity =
        p.capacity * std::max(sinTilt, p.minTilt) * speed * std::min(1.0f, d2 * inverseCapacityDepth);
      const float s = this->S[k];
      // Delta > 0: ground dissolved into the water; < 0: sediment laid down.
      this->Delta[k] = capacity > s ? dissolve * (capacity - s) : -deposit * (s - capacity);
      this->D[k] = d2 * evaporate;
      this->Outflow[k] += out * dt;
    }
  }
}

void PipeErosion::transportSediment()
{
  const int nx = this->NX, ny = this->NY;
  double eroded = 0.0, deposited = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : eroded, deposited)
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(j) * nx + i;
      const float delta = this->Delta[k];
      this->B[k] -= delta;
      if (delta > 0.0f)
      {
        this->Eroded[k] += delta, eroded += delta;
      }
      else
      {
        this->Deposited[k] -= delta, deposited -= delta;
      }
      // Suspended sediment after erosion, of this cell and (read, not written) of its neighbours.
      const auto suspended = [&](std::size_t c) { return this->S[c] + this->Delta[c]; };
      const float leaving = (this->FL[k] + this->FR[k] + this->FB[k] + this->FT[k]) * this->Q[k];
      float value = suspended(k) * (1.0f - leaving);
      if (i > 0)
      {
        value += suspended(k - 1) * this->FR[k - 1] * this->Q[k - 1];
      }
      if (i < nx - 1)
      {
        value += suspended(k + 1) * this->FL[k + 1] * this->Q[k + 1];
      }
      if (j > 0)
      {
        value += suspended(k - nx) * this->FT[k - nx] * this->Q[k - nx];
      }
      if (j < ny - 1)
      {
        value += suspended(k + nx) * this->FB[k + nx] * this->Q[k + nx];
      }
      this->S2[k] = value;
    }
  }
  this->S.swap(this->S2);
  const double area = static_cast<double>(this->LX) * this->LY;
  this->ErodedTotal += eroded * area;
  this->DepositedTotal += deposited * area;
}

ErosionMaps PipeErosion::maps() const
{
  ErosionMaps m;
  m.waterFlow = this->Outflow;
  const float time = this->Steps > 0 ? this->Settings.timeStep * static_cast<float>(this->Steps) : 1.0f;
  for (float& f : m.waterFlow)
  {
    f /= time;
  }
  m.sedimentDeposited = this->Deposited;
  m.erodedDepth = this->Eroded;
  return m;
}

SedimentBudget PipeErosion::budget() const
{
  SedimentBudget b;
  b.eroded = this->ErodedTotal;
  b.deposited = this->DepositedTotal;
  double suspended = 0.0;
  for (const float s : this->S)
  {
    suspended += s;
  }
  b.carried = suspended * this->LX * this->LY;
  return b;
}
} // namespace parafluid::terrain
