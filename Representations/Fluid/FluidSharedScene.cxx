#include "FluidSharedScene.h"

#include "FluidScreenTargets.h"
#include "parafluid/common/Communicator.h"

#include "vtkInformation.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPVRenderView.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

namespace parafluid
{
namespace
{
// A viewport rectangle as process 0 sends it: first pixel and size; an empty one means "nothing".
using Rect = std::array<std::int32_t, 4>;

std::vector<std::uint8_t> bytesOf(const void* data, std::size_t size)
{
  const auto* p = static_cast<const std::uint8_t*>(data);
  return std::vector<std::uint8_t>(p, p + size);
}

/// The colour (RGBA, 8 bits) and window depth of the framebuffer being drawn inside `rect` of the
/// viewport starting at `origin`, colours first.
std::vector<std::uint8_t> readScene(vtkOpenGLState* state, const int origin[2], const Rect& rect)
{
  const std::size_t pixels = static_cast<std::size_t>(rect[2]) * static_cast<std::size_t>(rect[3]);
  std::vector<std::uint8_t> scene(pixels * 8);
  GLint drawFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(origin[0] + rect[0], origin[1] + rect[1], rect[2], rect[3], GL_RGBA, GL_UNSIGNED_BYTE, scene.data());
  glReadPixels(origin[0] + rect[0], origin[1] + rect[1], rect[2], rect[3], GL_DEPTH_COMPONENT, GL_FLOAT,
               scene.data() + pixels * 4);
  state->PopReadFramebufferBinding();
  return scene;
}

/// Every pixel's nearest of the processes' `scenes` (readScene's colours then depths; a scene of
/// another size counts as drawing nothing): its colour and window depth, ties to the lower rank;
/// where none is nearer than the far plane, depth 1 and the first scene's own colour.
void compositeByDepth(const std::vector<std::vector<std::uint8_t>>& scenes, std::size_t pixels,
                      std::vector<std::uint8_t>& color, std::vector<float>& depth)
{
  color.assign(pixels * 4, 0);
  depth.assign(pixels, 1.0f);
  if (scenes[0].size() == pixels * 8)
  {
    std::memcpy(color.data(), scenes[0].data(), pixels * 4);
  }
  for (const auto& scene : scenes)
  {
    if (scene.size() != pixels * 8)
    {
      continue;
    }
    for (std::size_t i = 0; i < pixels; ++i)
    {
      float d;
      std::memcpy(&d, scene.data() + pixels * 4 + i * 4, sizeof(d));
      if (d < depth[i])
      {
        depth[i] = d;
        std::memcpy(color.data() + i * 4, scene.data() + i * 4, 4);
      }
    }
  }
}

/// The renderer's background at viewport row `y` of `height`, as 8-bit RGBA (VTK's gradient runs
/// from Background at the bottom to Background2 at the top).
std::array<std::uint8_t, 4> backgroundAt(vtkRenderer* renderer, int y, int height)
{
  const double* bottom = renderer->GetBackground();
  const double* top = renderer->GetGradientBackground() ? renderer->GetBackground2() : bottom;
  const double t = (static_cast<double>(y) + 0.5) / static_cast<double>(std::max(height, 1));
  std::array<std::uint8_t, 4> c{ 0, 0, 0, 255 };
  for (int k = 0; k < 3; ++k)
  {
    const double v = std::clamp(bottom[k] + t * (top[k] - bottom[k]), 0.0, 1.0);
    c[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(std::lround(255.0 * v));
  }
  return c;
}
} // namespace

SharedRendering sharedRenderingOf(vtkInformation* renderRequest, Communicator* processes)
{
  SharedRendering sharing;
  auto* view = vtkPVRenderView::SafeDownCast(renderRequest->Get(vtkPVView::VIEW()));
  if (!processes || !view)
  {
    return sharing;
  }
  const bool lod =
    renderRequest->Has(vtkPVRenderView::USE_LOD()) && renderRequest->Get(vtkPVRenderView::USE_LOD()) != 0;
  if (!(lod ? view->GetUseDistributedRenderingForLODRender() : view->GetUseDistributedRenderingForRender()))
  {
    return sharing;
  }
  // While the processes render, ParaView sets their renderers' background to black
  // (vtkSynchronizedRenderers' FixBackground); before the render it is still the view's.
  vtkRenderer* renderer = view->GetRenderer();
  sharing.Processes = processes;
  renderer->GetBackground(sharing.BackgroundBottom);
  renderer->GetBackground2(sharing.BackgroundTop);
  if (!renderer->GetGradientBackground())
  {
    std::copy(sharing.BackgroundBottom, sharing.BackgroundBottom + 3, sharing.BackgroundTop);
  }
  return sharing;
}

namespace
{
// Writes the composited scene (colour, and depth as a float texture) into the framebuffer.
constexpr const char* kWriteSceneFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D sceneColor;
uniform sampler2D sceneDepth;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(sceneColor, texCoord);
  gl_FragDepth = texture(sceneDepth, texCoord).r;
}
)";
/// The sky's depth on process 0 after a take-over: nearer than any other process's cleared 1, so
/// its (transparent) sky pixels, where the streaks are, win the depth compositing.
constexpr float kSkyDepth = 1.0f - 1.0e-6f;
} // namespace

SharedFrameTakeOver::SharedFrameTakeOver() = default;
SharedFrameTakeOver::~SharedFrameTakeOver() = default;

bool SharedFrameTakeOver::Run(const SharedRendering& sharing, vtkRenderer* renderer)
{
  Communicator* processes = sharing.Processes && sharing.Processes->size() > 1 ? sharing.Processes : nullptr;
  if (!processes)
  {
    return true;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  Rect rect{ 0, 0, 0, 0 };
  int origin[2] = { 0, 0 };
  renderer->GetTiledSizeAndOrigin(&rect[2], &rect[3], &origin[0], &origin[1]);
  const auto size = static_cast<std::size_t>(processes->size());
  std::vector<std::vector<std::uint8_t>> sends(size);
  vtkOpenGLState* state = window ? window->GetState() : nullptr;
  if (processes->rank() != 0)
  {
    if (state && rect[2] > 0 && rect[3] > 0)
    {
      sends[0] = readScene(state, origin, rect);
    }
    processes->exchange(sends);
    if (state)
    {
      // Process 0 now draws this process's part: nothing of it must win the compositing.
      vtkOpenGLState::ScopedglColorMask savedColorMask(state);
      vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
      vtkOpenGLState::ScopedglClearColor savedClearColor(state);
      state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      state->vtkglClearDepth(1.0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    return false;
  }
  auto received = processes->exchange(sends);
  if (!state || rect[2] <= 0 || rect[3] <= 0)
  {
    return true;
  }
  received[0] = readScene(state, origin, rect);
  const std::size_t pixels = static_cast<std::size_t>(rect[2]) * static_cast<std::size_t>(rect[3]);
  std::vector<std::uint8_t> color;
  std::vector<float> depth;
  compositeByDepth(received, pixels, color, depth); // process 0's own sky stays: transparent
  for (float& d : depth)
  {
    d = d < 1.0f ? d : kSkyDepth;
  }
  if (!this->Color)
  {
    this->Color = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
  }
  for (vtkTextureObject* t : { this->Color.Get(), this->Depth.Get() })
  {
    t->SetContext(window);
    t->SetMinificationFilter(vtkTextureObject::Nearest);
    t->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  this->Color->Create2DFromRaw(rect[2], rect[3], 4, VTK_UNSIGNED_CHAR, color.data());
  this->Depth->Create2DFromRaw(rect[2], rect[3], 1, VTK_FLOAT, depth.data());
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(window, nullptr, kWriteSceneFS, ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program)
  {
    return true; // did not compile (the shader cache said why): the rain is drawn over process 0's part
  }
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
  vtkOpenGLState::ScopedglColorMask savedColorMask(state);
  state->vtkglViewport(origin[0], origin[1], rect[2], rect[3]);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  this->Color->Activate();
  this->Depth->Activate();
  this->Quad->Program->SetUniformi("sceneColor", this->Color->GetTextureUnit());
  this->Quad->Program->SetUniformi("sceneDepth", this->Depth->GetTextureUnit());
  this->Quad->Render();
  this->Color->Deactivate();
  this->Depth->Deactivate();
  return true;
}

void SharedFrameTakeOver::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  for (vtkTextureObject* t : { this->Color.Get(), this->Depth.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
}

FluidSharedScene::FluidSharedScene(const SharedRendering& sharing, vtkRenderer* renderer)
  : Processes(sharing.Processes && sharing.Processes->size() > 1 ? sharing.Processes : nullptr)
{
  this->Renderer = renderer;
  if (this->Processes && this->Processes->rank() == 0 && renderer)
  {
    this->Restore = true;
    renderer->GetBackground(this->Background[0]);
    renderer->GetBackground2(this->Background[1]);
    this->Gradient = renderer->GetGradientBackground();
    renderer->SetBackground(const_cast<double*>(sharing.BackgroundBottom));
    renderer->SetBackground2(const_cast<double*>(sharing.BackgroundTop));
    renderer->SetGradientBackground(true);
  }
}

FluidSharedScene::~FluidSharedScene()
{
  if (this->Restore)
  {
    this->Renderer->SetBackground(this->Background[0]);
    this->Renderer->SetBackground2(this->Background[1]);
    this->Renderer->SetGradientBackground(this->Gradient);
  }
  if (this->Processes && this->Processes->rank() == 0 && !this->Done)
  {
    std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(this->Processes->size()));
    const Rect nothing{ 0, 0, 0, 0 };
    for (std::size_t r = 1; r < sends.size(); ++r)
    {
      sends[r] = bytesOf(nothing.data(), sizeof(nothing));
    }
    this->Processes->exchange(sends);
  }
}

bool FluidSharedScene::Lends() const
{
  return this->Processes && this->Processes->rank() != 0;
}

void FluidSharedScene::Lend()
{
  const auto size = static_cast<std::size_t>(this->Processes->size());
  const auto told = this->Processes->exchange(std::vector<std::vector<std::uint8_t>>(size));
  Rect rect{ 0, 0, 0, 0 };
  if (told[0].size() == sizeof(rect))
  {
    std::memcpy(rect.data(), told[0].data(), sizeof(rect));
  }
  if (rect[2] <= 0 || rect[3] <= 0)
  {
    return;
  }
  std::vector<std::vector<std::uint8_t>> sends(size);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(this->Renderer ? this->Renderer->GetRenderWindow() : nullptr);
  if (window)
  {
    int viewport[2], origin[2];
    this->Renderer->GetTiledSizeAndOrigin(&viewport[0], &viewport[1], &origin[0], &origin[1]);
    sends[0] = readScene(window->GetState(), origin, rect);
  }
  // A process without a window sends nothing and counts as drawing nothing there.
  this->Processes->exchange(sends);
}

void FluidSharedScene::Composite(const FluidFrame& frame, FluidScreenTargets& targets, bool withColor)
{
  if (!this->Processes || this->Done)
  {
    return;
  }
  this->Done = true;
  const Rect rect{ frame.RectMin[0], frame.RectMin[1], frame.RectWidth(), frame.RectHeight() };
  const auto size = static_cast<std::size_t>(this->Processes->size());
  std::vector<std::vector<std::uint8_t>> sends(size);
  for (std::size_t r = 1; r < size; ++r)
  {
    sends[r] = bytesOf(rect.data(), sizeof(rect));
  }
  this->Processes->exchange(sends);
  if (rect[2] <= 0 || rect[3] <= 0)
  {
    return;
  }
  auto received = this->Processes->exchange(std::vector<std::vector<std::uint8_t>>(size));
  received[0] = readScene(frame.State, frame.Origin, rect);
  const std::size_t pixels = static_cast<std::size_t>(rect[2]) * static_cast<std::size_t>(rect[3]);
  std::vector<std::uint8_t> color;
  std::vector<float> depth;
  compositeByDepth(received, pixels, color, depth);
  for (std::size_t i = 0; i < pixels; ++i)
  {
    if (depth[i] >= 1.0f)
    {
      const int y = rect[1] + static_cast<int>(i / static_cast<std::size_t>(rect[2]));
      const auto sky = backgroundAt(frame.Renderer, y, frame.Size[1]); // the view's, set above
      std::memcpy(color.data() + i * 4, sky.data(), 4);
    }
  }
  frame.State->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  targets.OpaqueDepth->Bind();
  glTexSubImage2D(GL_TEXTURE_2D, 0, rect[0], rect[1], rect[2], rect[3], GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  targets.OpaqueDepth->Deactivate();
  if (withColor)
  {
    targets.OpaqueColor->Bind();
    glTexSubImage2D(GL_TEXTURE_2D, 0, rect[0], rect[1], rect[2], rect[3], GL_RGBA, GL_UNSIGNED_BYTE, color.data());
    targets.OpaqueColor->Deactivate();
  }
}
} // namespace parafluid
