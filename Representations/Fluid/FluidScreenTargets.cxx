#include "FluidScreenTargets.h"

#include "FluidFrame.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace parafluid
{
vtkSmartPointer<vtkTextureObject> makeScreenTexture(vtkOpenGLRenderWindow* window)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture;
}

void FluidScreenTargets::Ensure(vtkOpenGLRenderWindow* window, int width, int height, int thicknessFactor, bool colors,
                                bool toon)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
    glGenVertexArrays(1, &this->EmptyVAO);
  }
  const bool resize = width != this->Width || height != this->Height;
  const bool resizeThickness = resize || thicknessFactor != this->ThicknessFactor;
  auto single = [&](vtkSmartPointer<vtkTextureObject>& t, int w, int h, bool linear, bool changed)
  {
    if (!t)
    {
      t = makeScreenTexture(window);
      t->SetInternalFormat(GL_R32F);
      t->SetFormat(GL_RED);
      if (linear)
      {
        t->SetMinificationFilter(vtkTextureObject::Linear);
        t->SetMagnificationFilter(vtkTextureObject::Linear);
      }
      t->Allocate2D(w, h, 1, VTK_FLOAT);
    }
    else if (changed)
    {
      t->Resize(w, h);
    }
  };
  single(this->Depth[0], width, height, false, resize);
  single(this->Depth[1], width, height, false, resize);
  const int tw = (width + thicknessFactor - 1) / thicknessFactor, th = (height + thicknessFactor - 1) / thicknessFactor;
  single(this->Thickness[0], tw, th, true, resizeThickness);
  single(this->Thickness[1], tw, th, true, resizeThickness);
  this->ThicknessFactor = thicknessFactor;
  auto depth = [&](vtkSmartPointer<vtkTextureObject>& t)
  {
    if (!t)
    {
      t = makeScreenTexture(window);
      t->AllocateDepth(width, height, vtkTextureObject::Float32);
    }
    else if (resize)
    {
      t->Resize(width, height);
    }
  };
  depth(this->OpaqueDepth);
  depth(this->SplatDepth);
  auto rgba = [&](vtkSmartPointer<vtkTextureObject>& t)
  {
    if (!t)
    {
      t = makeScreenTexture(window);
      t->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    }
    else if (resize)
    {
      t->Resize(width, height);
    }
  };
  rgba(this->OpaqueColor);
  if (colors || this->ParticleColors)
  {
    rgba(this->ParticleColors);
  }
  if (toon || this->Lines)
  {
    for (auto& t : this->Tensor)
    {
      if (!t)
      {
        t = makeScreenTexture(window);
        t->SetInternalFormat(GL_RGBA32F);
        t->SetFormat(GL_RGBA);
        t->Allocate2D(width, height, 4, VTK_FLOAT);
      }
      else if (resize)
      {
        t->Resize(width, height);
      }
    }
    single(this->Lines, width, height, false, resize);
  }
  this->Width = width;
  this->Height = height;
}

void FluidScreenTargets::CopyOpaqueScene(const FluidFrame& frame, bool withColor)
{
  // Read from the framebuffer being drawn (the read binding may point elsewhere, e.g. at
  // ParaView's display buffer).
  vtkOpenGLState* state = frame.State;
  GLint drawFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  state->PushReadFramebufferBinding();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
  // (vtkTextureObject::CopyFromFrameBuffer re-creates the texture at the copied size; the
  // targets must keep the viewport's size, so copy into the rectangle ourselves.)
  auto copyRect = [&](vtkTextureObject* target)
  {
    target->Bind();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, frame.RectMin[0], frame.RectMin[1], frame.Origin[0] + frame.RectMin[0],
                        frame.Origin[1] + frame.RectMin[1], frame.RectWidth(), frame.RectHeight());
    target->Deactivate();
  };
  copyRect(this->OpaqueDepth);
  if (withColor)
  {
    copyRect(this->OpaqueColor);
  }
  state->PopReadFramebufferBinding();
}

void FluidScreenTargets::Release(vtkWindow* window)
{
  for (vtkTextureObject* t :
       { this->OpaqueDepth.Get(), this->OpaqueColor.Get(), this->SplatDepth.Get(), this->ParticleColors.Get(),
         this->Depth[0].Get(), this->Depth[1].Get(), this->Thickness[0].Get(), this->Thickness[1].Get(),
         this->Tensor[0].Get(), this->Tensor[1].Get(), this->Lines.Get() })
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  if (this->EmptyVAO && window)
  {
    static_cast<vtkOpenGLRenderWindow*>(window)->MakeCurrent();
    glDeleteVertexArrays(1, &this->EmptyVAO);
  }
  this->OpaqueDepth = this->OpaqueColor = this->SplatDepth = this->ParticleColors = nullptr;
  this->Depth = {};
  this->Thickness = {};
  this->Tensor = {};
  this->Lines = nullptr;
  this->Framebuffer = nullptr;
  this->EmptyVAO = 0;
  this->Width = this->Height = 0;
}
} // namespace parafluid
