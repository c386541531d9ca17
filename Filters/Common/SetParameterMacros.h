#pragma once
// Setters for properties that cannot refuse a value at run time (a representation's shading
// parameters are used while rendering, where an error has nowhere to go): a NaN or infinite value
// is ignored with a warning that names the property, and a finite one outside the property's range
// is clamped to it (as the GUI's slider does). VTK's own vtkSetClampMacro lets NaN through, which
// then reaches the shaders.
#include <cmath>
#include <type_traits>

namespace parafluid::vtk
{
template<class T>
bool isFiniteValue(T value)
{
  if constexpr (std::is_floating_point_v<T>)
  {
    return std::isfinite(value);
  }
  else
  {
    return true;
  }
}
} // namespace parafluid::vtk

#define vtkPFSetClampMacro(name, type, min, max)                                                                       \
  virtual void Set##name(type _arg)                                                                                    \
  {                                                                                                                    \
    if (!parafluid::vtk::isFiniteValue(_arg))                                                                          \
    {                                                                                                                  \
      vtkWarningMacro(<< #name " = " << _arg << " is ignored: it must be a finite number from " << (min) << " to "     \
                      << (max));                                                                                       \
      return;                                                                                                          \
    }                                                                                                                  \
    const type clamped = _arg < (min) ? (min) : (_arg > (max) ? (max) : _arg);                                         \
    if (this->name != clamped)                                                                                         \
    {                                                                                                                  \
      this->name = clamped;                                                                                            \
      this->Modified();                                                                                                \
    }                                                                                                                  \
  }                                                                                                                    \
  virtual type Get##name##MinValue()                                                                                   \
  {                                                                                                                    \
    return (min);                                                                                                      \
  }                                                                                                                    \
  virtual type Get##name##MaxValue()                                                                                   \
  {                                                                                                                    \
    return (max);                                                                                                      \
  }

#define vtkPFSetFiniteMacro(name, type)                                                                                \
  virtual void Set##name(type _arg)                                                                                    \
  {                                                                                                                    \
    if (!parafluid::vtk::isFiniteValue(_arg))                                                                          \
    {                                                                                                                  \
      vtkWarningMacro(<< #name " = " << _arg << " is ignored: it must be a finite number");                            \
      return;                                                                                                          \
    }                                                                                                                  \
    if (this->name != _arg)                                                                                            \
    {                                                                                                                  \
      this->name = _arg;                                                                                               \
      this->Modified();                                                                                                \
    }                                                                                                                  \
  }

#define vtkPFSetFiniteVector3Macro(name, type)                                                                         \
  virtual void Set##name(type _arg1, type _arg2, type _arg3)                                                           \
  {                                                                                                                    \
    if (!std::isfinite(_arg1) || !std::isfinite(_arg2) || !std::isfinite(_arg3))                                       \
    {                                                                                                                  \
      vtkWarningMacro(<< #name " = (" << _arg1 << ", " << _arg2 << ", " << _arg3                                       \
                      << ") is ignored: each component must be a finite number");                                      \
      return;                                                                                                          \
    }                                                                                                                  \
    if (this->name[0] != _arg1 || this->name[1] != _arg2 || this->name[2] != _arg3)                                    \
    {                                                                                                                  \
      this->name[0] = _arg1;                                                                                           \
      this->name[1] = _arg2;                                                                                           \
      this->name[2] = _arg3;                                                                                           \
      this->Modified();                                                                                                \
    }                                                                                                                  \
  }                                                                                                                    \
  virtual void Set##name(const type _arg[3])                                                                           \
  {                                                                                                                    \
    this->Set##name(_arg[0], _arg[1], _arg[2]);                                                                        \
  }
