/**
 * @class vtkPFRainRepresentation
 * @brief ParaView's "Rain" and "Rain Splashes" representations (Kind): the Rain filter's drops
 * as streaks lit by precomputed radiance transfer, or its splashes as sprites.
 *
 * Delivers the input's points with their point arrays (each rank its own piece) to a
 * vtkPFRainMapper drawn after the rest of the scene (vtkPFScreenSpaceFluidActor), and forwards the
 * settings.
 */
#pragma once

#include "ParaFluidRainRepresentationsModule.h"
#include "vtkPVDataRepresentation.h"
#include "vtkSmartPointer.h"

#include <memory>

class vtkPFRainMapper;
class vtkPFScreenSpaceFluidActor;
class vtkPolyData;
namespace parafluid
{
class Communicator;
}

class PARAFLUIDRAINREPRESENTATIONS_EXPORT vtkPFRainRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkPFRainRepresentation* New();
  vtkTypeMacro(vtkPFRainRepresentation, vtkPVDataRepresentation);

  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

  //@{
  /// Forwarded to the mapper (vtkPFRainMapper).
  void SetKind(int kind);
  void SetDisplayMode(int mode);
  void SetRefractiveIndex(double index);
  void SetBrightness(double brightness);
  void SetOpacity(double opacity);
  void SetFogDistance(double distance);
  void SetWidthScale(double scale);
  void SetRasteriser(int rasteriser);
  /// Whether the last frame's streaks were drawn on the CPU (the mapper's).
  int GetLastDrawnOnCpu();
  void SetSplashSize(double size);
  void SetSplashLifetime(double lifetime);
  void SetEnvironmentImage(int face, const char* file);
  //@}

protected:
  vtkPFRainRepresentation();
  ~vtkPFRainRepresentation() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkPFRainRepresentation(const vtkPFRainRepresentation&) = delete;
  void operator=(const vtkPFRainRepresentation&) = delete;

  vtkSmartPointer<vtkPFRainMapper> Mapper;
  vtkSmartPointer<vtkPFScreenSpaceFluidActor> Actor;
  vtkSmartPointer<vtkPolyData> Points;
  // The session's processes (null in a serial one): the drops are drawn on process 0.
  std::unique_ptr<parafluid::Communicator> Processes;
  bool ProcessesAsked = false;
};
