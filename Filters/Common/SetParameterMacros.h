#pragma once
// Setters for properties that cannot refuse a value at run time (a representation's shading
// parameters are used while rendering, where an error has nowhere to go): a NaN or infinite value
// is ignored with a warning that names the property, and a finite one outside the property's range
// is clamped to it (as the GUI's slider does). VTK's own vtkSetClampMacro lets NaN through, which
// then reaches the shaders.
#include <cmath>
#include <limits>
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

// A triple: NaN or infinite components are ignored with a warning (`rule` says what is allowed),
// finite ones clamped to [min, max] each.
#define vtkPFSetVector3Impl(name, type, min, max, rule)                                                                \
  virtual void Set##name(type _arg1, type _arg2, type _arg3)                                                           \
  {                                                                                                                    \
    if (!std::isfinite(_arg1) || !std::isfinite(_arg2) || !std::isfinite(_arg3))                                       \
    {                                                                                                                  \
      vtkWarningMacro(<< #name " = (" << _arg1 << ", " << _arg2 << ", " << _arg3 << ") is ignored: " rule);            \
      return;                                                                                                          \
    }                                                                                                                  \
    const type c[3] = { _arg1 < (min) ? (min) : (_arg1 > (max) ? (max) : _arg1),                                       \
                        _arg2 < (min) ? (min) : (_arg2 > (max) ? (max) : _arg2),                                       \
                        _arg3 < (min) ? (min) : (_arg3 > (max) ? (max) : _arg3) };                                     \
    if (this->name[0] != c[0] || this->name[1] != c[1] || this->name[2] != c[2])                                       \
    {                                                                                                                  \
      this->name[0] = c[0];                                                                                            \
      this->name[1] = c[1];                                                                                            \
      this->name[2] = c[2];                                                                                            \
      this->Modified();                                                                                                \
    }                                                                                                                  \
  }                                                                                                                    \
  virtual void Set##name(const type _arg[3])                                                                           \
  {                                                                                                                    \
    this->Set##name(_arg[0], _arg[1], _arg[2]);                                                                        \
  }

#define vtkPFSetFiniteVector3Macro(name, type)                                                                         \
  vtkPFSetVector3Impl(name, type, -std::numeric_limits<type>::infinity(), std::numeric_limits<type>::infinity(),       \
                      << "each component must be a finite number")

// A colour or other triple clamped to [min, max] each (the XML's colour domain).
#define vtkPFSetClampVector3Macro(name, type, min, max)                                                                \
  vtkPFSetVector3Impl(name, type, min, max,                                                                            \
                      << "each component must be a finite number from " << (min) << " to " << (max))
