/**
 * @class vtkPFProceduralTerrain
 * @brief Source: a height field from fractal gradient noise or diamond-square.
 *
 * Over Extent metres from Origin at Resolution samples: baseHeight + HeightScale times fBm,
 * turbulence or ridged multifractal of Perlin's improved noise (Octaves, Lacunarity,
 * Persistence, first wavelength FeatureSize), optionally domain-warped (WarpStrength metres, a
 * warp fBm of wavelength WarpScale and WarpOctaves octaves), or diamond-square with Roughness H.
 * The same Seed gives the same terrain on any thread count. Outputs: see vtkPFTerrainAlgorithm.
 */
#pragma once

#include "vtkPFTerrainAlgorithm.h"

#include "EnumerationChoice.h"

#include "parafluid/terrain/TerrainGenerator.h"

class PARAFLUIDTERRAINFILTERS_EXPORT vtkPFProceduralTerrain : public vtkPFTerrainAlgorithm
{
public:
  static vtkPFProceduralTerrain* New();
  vtkTypeMacro(vtkPFProceduralTerrain, vtkPFTerrainAlgorithm);

  vtkSetVector2Macro(Origin, double);
  vtkGetVector2Macro(Origin, double);
  vtkSetVector2Macro(Extent, double);
  vtkGetVector2Macro(Extent, double);
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  /// 0 fractal noise, 1 diamond-square.
  void SetMethod(int value)
  {
    if (parafluid::vtk::isChoice(this, "Method", value, { "Fractal Noise", "Diamond-Square" }, this->GetMethod()))
    {
      this->SetSetting(this->Settings.method, static_cast<parafluid::terrain::TerrainMethod>(value));
    }
  }
  int GetMethod() const { return static_cast<int>(this->Settings.method); }
  /// 0 fBm, 1 turbulence, 2 ridged.
  void SetFractalType(int value)
  {
    if (parafluid::vtk::isChoice(this, "FractalType", value, { "fBm", "Turbulence", "Ridged" }, this->GetFractalType()))
    {
      this->SetSetting(this->Settings.fractal.type, static_cast<parafluid::terrain::FractalType>(value));
    }
  }
  int GetFractalType() const { return static_cast<int>(this->Settings.fractal.type); }
  void SetSeed(int value)
  {
    this->SetSetting(this->Settings.seed, static_cast<std::uint64_t>(static_cast<std::uint32_t>(value)));
  }
  int GetSeed() const { return static_cast<int>(this->Settings.seed); }
  void SetOctaves(int value) { this->SetSetting(this->Settings.fractal.octaves, value); }
  int GetOctaves() const { return this->Settings.fractal.octaves; }
  void SetLacunarity(double value) { this->SetSetting(this->Settings.fractal.lacunarity, static_cast<float>(value)); }
  double GetLacunarity() const { return this->Settings.fractal.lacunarity; }
  void SetPersistence(double value) { this->SetSetting(this->Settings.fractal.persistence, static_cast<float>(value)); }
  double GetPersistence() const { return this->Settings.fractal.persistence; }
  void SetFeatureSize(double value) { this->SetSetting(this->Settings.featureSize, value); }
  double GetFeatureSize() const { return this->Settings.featureSize; }
  void SetWarpStrength(double value) { this->SetSetting(this->Settings.warpStrength, value); }
  double GetWarpStrength() const { return this->Settings.warpStrength; }
  void SetWarpScale(double value) { this->SetSetting(this->Settings.warpScale, value); }
  double GetWarpScale() const { return this->Settings.warpScale; }
  void SetWarpOctaves(int value) { this->SetSetting(this->Settings.warpOctaves, value); }
  int GetWarpOctaves() const { return this->Settings.warpOctaves; }
  void SetRoughness(double value) { this->SetSetting(this->Settings.roughness, value); }
  double GetRoughness() const { return this->Settings.roughness; }
  void SetHeightScale(double value) { this->SetSetting(this->Settings.heightScale, value); }
  double GetHeightScale() const { return this->Settings.heightScale; }
  void SetBaseHeight(double value) { this->SetSetting(this->Settings.baseHeight, value); }
  double GetBaseHeight() const { return this->Settings.baseHeight; }

protected:
  vtkPFProceduralTerrain();
  ~vtkPFProceduralTerrain() override = default;
  bool ComputeTerrain(vtkInformationVector** inputVector, parafluid::terrain::ElevationGrid& grid,
                      NamedArrays& arrays) override;
  bool TerrainGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2], double spacing[2]) override;
  const char* Label() const override { return "Procedural Terrain"; }

private:
  vtkPFProceduralTerrain(const vtkPFProceduralTerrain&) = delete;
  void operator=(const vtkPFProceduralTerrain&) = delete;
  parafluid::terrain::TerrainSettings Settings;
  double Origin[2] = { 0.0, 0.0 };
  double Extent[2] = { 1000.0, 1000.0 };
  int Resolution[2] = { 257, 257 };
};
