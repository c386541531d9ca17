/**
 * @class vtkPFHydraulicErosion
 * @brief Filter: erodes a terrain (2-D height image) by water, with droplets or virtual pipes.
 *
 * Method 0 (Droplets): Drops drops each run downhill with Inertia, carry sediment up to
 * Capacity x slope x speed x water, erode (ErodeRate, under a brush of Radius cells) or deposit
 * (DepositRate) and evaporate (Evaporation) for at most MaxLifetime steps; the same Seed gives
 * the same result on any thread count. Method 1 (Virtual Pipes, Mei et al. 2007): Iterations
 * steps of TimeStep seconds of RainRate rain flowing through pipes between cells, dissolving
 * (DissolveRate) and depositing (PipeDepositRate) sediment against SedimentCapacity.
 * Output arrays: `elevation` (eroded), `water_flow`, `sediment_deposited` [m], `eroded_depth` [m]
 * (and `water_depth` [m] for pipes). ErodedVolume, DepositedVolume, CarriedVolume [m^3]: the budget.
 */
#pragma once

#include "vtkPFTerrainAlgorithm.h"

#include "AssignIfChanged.h"
#include "EnumerationChoice.h"

#include "parafluid/terrain/DropletErosion.h"
#include "parafluid/terrain/PipeErosion.h"

class PARAFLUIDTERRAINFILTERS_EXPORT vtkPFHydraulicErosion : public vtkPFTerrainAlgorithm
{
public:
  static vtkPFHydraulicErosion* New();
  vtkTypeMacro(vtkPFHydraulicErosion, vtkPFTerrainAlgorithm);

  /// 0 droplets, 1 virtual pipes.
  void SetMethod(int value)
  {
    if (parafluid::vtk::isChoice(this, "Method", value, { "Droplets", "Virtual Pipes" }, this->Method))
    {
      parafluid::vtk::assignIfChanged(this, this->Method, value);
    }
  }
  vtkGetMacro(Method, int);
  // Droplets
  void SetDrops(int value) { this->SetSetting(this->Droplets.drops, static_cast<long long>(value)); }
  int GetDrops() const { return static_cast<int>(this->Droplets.drops); }
  void SetInertia(double value) { this->SetSetting(this->Droplets.inertia, static_cast<float>(value)); }
  double GetInertia() const { return this->Droplets.inertia; }
  void SetCapacity(double value) { this->SetSetting(this->Droplets.capacity, static_cast<float>(value)); }
  double GetCapacity() const { return this->Droplets.capacity; }
  void SetErodeRate(double value) { this->SetSetting(this->Droplets.erodeRate, static_cast<float>(value)); }
  double GetErodeRate() const { return this->Droplets.erodeRate; }
  void SetDepositRate(double value) { this->SetSetting(this->Droplets.depositRate, static_cast<float>(value)); }
  double GetDepositRate() const { return this->Droplets.depositRate; }
  void SetEvaporation(double value) { this->SetSetting(this->Droplets.evaporation, static_cast<float>(value)); }
  double GetEvaporation() const { return this->Droplets.evaporation; }
  void SetRadius(double value) { this->SetSetting(this->Droplets.radius, static_cast<float>(value)); }
  double GetRadius() const { return this->Droplets.radius; }
  void SetMaxLifetime(int value) { this->SetSetting(this->Droplets.maxSteps, value); }
  int GetMaxLifetime() const { return this->Droplets.maxSteps; }
  void SetSeed(int value)
  {
    this->SetSetting(this->Droplets.seed, static_cast<std::uint64_t>(static_cast<std::uint32_t>(value)));
  }
  int GetSeed() const { return static_cast<int>(this->Droplets.seed); }
  // Virtual pipes
  vtkSetMacro(Iterations, int);
  vtkGetMacro(Iterations, int);
  void SetTimeStep(double value) { this->SetSetting(this->Pipes.timeStep, static_cast<float>(value)); }
  double GetTimeStep() const { return this->Pipes.timeStep; }
  void SetRainRate(double value) { this->SetSetting(this->Pipes.rainRate, static_cast<float>(value)); }
  double GetRainRate() const { return this->Pipes.rainRate; }
  void SetSedimentCapacity(double value) { this->SetSetting(this->Pipes.capacity, static_cast<float>(value)); }
  double GetSedimentCapacity() const { return this->Pipes.capacity; }
  void SetDissolveRate(double value) { this->SetSetting(this->Pipes.dissolveRate, static_cast<float>(value)); }
  double GetDissolveRate() const { return this->Pipes.dissolveRate; }
  void SetPipeDepositRate(double value) { this->SetSetting(this->Pipes.depositRate, static_cast<float>(value)); }
  double GetPipeDepositRate() const { return this->Pipes.depositRate; }
  void SetPipeEvaporation(double value) { this->SetSetting(this->Pipes.evaporation, static_cast<float>(value)); }
  double GetPipeEvaporation() const { return this->Pipes.evaporation; }

  /// Volumes of the last run [m^3] (also in the output's field data).
  double GetErodedVolume() const { return this->Budget.eroded; }
  double GetDepositedVolume() const { return this->Budget.deposited; }
  double GetCarriedVolume() const { return this->Budget.carried; }

protected:
  vtkPFHydraulicErosion();
  ~vtkPFHydraulicErosion() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  bool ComputeTerrain(vtkInformationVector** inputVector, parafluid::terrain::ElevationGrid& grid,
                      NamedArrays& arrays) override;
  bool TerrainGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2], double spacing[2]) override;
  const char* Label() const override { return "Hydraulic Erosion"; }

private:
  vtkPFHydraulicErosion(const vtkPFHydraulicErosion&) = delete;
  void operator=(const vtkPFHydraulicErosion&) = delete;
  int Method = 0;
  int Iterations = 500;
  parafluid::terrain::DropletSettings Droplets;
  parafluid::terrain::PipeSettings Pipes;
  parafluid::terrain::SedimentBudget Budget;
};
