#include "RainStreakCpuPass.h"

#include "RainFrame.h"

#include "vtkMatrix4x4.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cstring>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace parafluid
{
namespace
{
// The streaks' image over the scene: premultiplied, so ONE / ONE_MINUS_SRC_ALPHA blending gives
// rgb + (1 - a) scene, what blending every streak in order over the scene gives.
const char* const kCompositeFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform sampler2D streaks;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(streaks, texCoord);
}
)";

/// The math matrix of one of VTK's key matrices (stored transposed, ready to upload), row-major.
std::array<float, 16> rowMajor(vtkMatrix4x4* transposed)
{
  std::array<float, 16> m{};
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[static_cast<std::size_t>(4 * r + c)] = static_cast<float>(transposed->GetElement(c, r));
    }
  }
  return m;
}

int threadCount()
{
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}
} // namespace

RainStreakCpuPass::RainStreakCpuPass() = default;
RainStreakCpuPass::~RainStreakCpuPass() = default;

bool RainStreakCpuPass::SoftwareRenderer()
{
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!name)
  {
    return false;
  }
  for (const char* software : { "llvmpipe", "softpipe", "SWR", "Software Rasterizer" })
  {
    if (std::strstr(name, software))
    {
      return true;
    }
  }
  return false;
}

bool RainStreakCpuPass::Run(const RainFrame& frame, const std::vector<float>& drops,
                            const rain::RadianceTable& radiance, const rain::StreakLook& look)
{
  const int width = static_cast<int>(frame.Viewport[0]), height = static_cast<int>(frame.Viewport[1]);
  if (width <= 0 || height <= 0)
  {
    return true;
  }
  // The compositing program first: without it the streaks go to the GPU path, undrawn here.
  if (!this->Quad)
  {
    this->Quad.reset(new vtkOpenGLQuadHelper(frame.Window, nullptr, kCompositeFS, ""));
  }
  else
  {
    frame.Window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    return false;
  }
  vtkOpenGLState* state = frame.State;
  // The scene's depth, from the framebuffer being drawn into.
  this->Depth.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  unsigned int drawBinding = 0, drawBuffer = 0;
  state->GetCurrentDrawFramebufferState(drawBinding, drawBuffer);
  for (int stale = 0; stale < 16 && glGetError() != GL_NO_ERROR; ++stale)
  {
    // errors left by others: the one read below must be the read's own
  }
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawBinding);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(frame.Origin[0], frame.Origin[1], width, height, GL_DEPTH_COMPONENT, GL_FLOAT, this->Depth.data());
  const bool read = glGetError() == GL_NO_ERROR;
  state->PopReadFramebufferBinding();
  if (!read)
  {
    return false;
  }

  rain::StreakCamera camera;
  camera.worldToView = rowMajor(frame.WorldToView);
  camera.viewToClip = rowMajor(frame.ViewToClip);
  camera.width = width;
  camera.height = height;
  camera.eye = { frame.Eye[0], frame.Eye[1], frame.Eye[2] };
  this->Raster.draw(drops.data(), drops.size() / 8, camera, look, radiance, this->Depth.data(), this->Image,
                    threadCount());

  if (!this->Texture)
  {
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
    this->Texture->SetContext(frame.Window);
    this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  if (this->Texture->GetWidth() != static_cast<unsigned int>(width) ||
      this->Texture->GetHeight() != static_cast<unsigned int>(height))
  {
    this->Texture->ReleaseGraphicsResources(frame.Window);
    this->Texture->SetInternalFormat(GL_RGBA32F);
    this->Texture->SetFormat(GL_RGBA);
    this->Texture->SetDataType(GL_FLOAT);
    this->Texture->Create2DFromRaw(width, height, 4, VTK_FLOAT, this->Image.data());
  }
  else
  {
    this->Texture->Bind();
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, this->Image.data());
  }

  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  this->Texture->Activate();
  this->Quad->Program->SetUniformi("streaks", this->Texture->GetTextureUnit());
  this->Quad->Render();
  this->Texture->Deactivate();
  return true;
}

void RainStreakCpuPass::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Texture = nullptr;
  }
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
}
} // namespace parafluid
