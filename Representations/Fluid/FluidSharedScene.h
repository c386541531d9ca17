#pragma once
// Screen-space fluid rendered by several processes (pvserver or pvbatch under MPI, IceT
// compositing): process 0 holds every particle and draws the fluid; it needs the opaque scene
// behind the fluid as all processes drew it, not only its own part, or the water refracts and
// attenuates the black of an empty framebuffer. Each frame the other processes send process 0
// their colour and depth inside the fluid's rectangle, and process 0 composites them by depth
// into the targets the fluid passes read. ParaView then composites the processes' images by depth
// as usual: the fluid's pixels come from process 0, the rest from whoever is nearest.
#include "FluidFrame.h"

#include "vtkSmartPointer.h"

#include <memory>

class vtkInformation;
class vtkOpenGLQuadHelper;
class vtkTextureObject;
class vtkWindow;

namespace parafluid
{
class Communicator;
class FluidScreenTargets;

/// How a view's rendering is shared this frame: the rendering processes (null when one process
/// renders) and the view's background, which ParaView paints only after compositing (the
/// processes' renderers draw on black meanwhile).
struct SharedRendering
{
  Communicator* Processes = nullptr;
  double BackgroundBottom[3] = { 0, 0, 0 };
  double BackgroundTop[3] = { 0, 0, 0 };
};

/// How the view of a representation's REQUEST_RENDER renders this frame: shared when `processes`
/// (the session's, null in a serial one) all render it for compositing; the view's background read
/// now, before the render begins.
SharedRendering sharedRenderingOf(vtkInformation* renderRequest, Communicator* processes);

/// For looks that blend into the framebuffer (rain streaks): each frame the other processes send
/// process 0 their whole viewport's colour and depth and clear theirs, and process 0 writes the
/// composite into its framebuffer, so that it holds the whole scene and its pixels win the
/// compositing (the sky a hair nearer than the far plane, left transparent for ParaView's
/// background). Process 0 then blends over the scene as a builtin session does.
class SharedFrameTakeOver
{
public:
  SharedFrameTakeOver();
  ~SharedFrameTakeOver();
  /// Collective in a shared render. Whether this process draws: process 0, or any process when the
  /// render is not shared.
  bool Run(const SharedRendering& sharing, vtkRenderer* renderer);
  void Release(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkSmartPointer<vtkTextureObject> Color, Depth;
};

/// One frame's sharing of the opaque scene. Every process of a shared render makes one, at the same
/// point of its fluid mapper's Render; all calls are collective.
class FluidSharedScene
{
public:
  /// On process 0 of a shared render, `renderer` shows the view's background until the end of the
  /// frame, so that the fluid reflects and refracts the sky the composited image will have.
  FluidSharedScene(const SharedRendering& sharing, vtkRenderer* renderer);
  /// Process 0, when it composited nothing this frame (nothing to draw), tells the others so; the
  /// renderer's own background comes back.
  ~FluidSharedScene();

  /// Whether this process only lends its scene (a shared render, and not process 0).
  bool Lends() const;
  /// The lending processes: wait for process 0's rectangle and send their colour and depth in it.
  void Lend();
  /// Process 0, after targets.CopyOpaqueScene(frame, withColor): replaces the targets' opaque depth
  /// (and colour when `withColor`) inside the frame's rectangle by every process's scene composited
  /// by depth, the view's background where no process drew anything. Does nothing when the
  /// render is not shared.
  void Composite(const FluidFrame& frame, FluidScreenTargets& targets, bool withColor);

  FluidSharedScene(const FluidSharedScene&) = delete;
  FluidSharedScene& operator=(const FluidSharedScene&) = delete;

private:
  Communicator* Processes = nullptr;
  vtkRenderer* Renderer = nullptr;
  double Background[2][3] = {}; // the renderer's own, restored at the end
  bool Gradient = false;
  bool Restore = false;
  bool Done = false;
};
} // namespace parafluid
