#pragma once
// Owns one HDF5 identifier and closes it with the matching H5?close, so that every early error
// return in the reader and writer releases what it opened.
#include "parafluid/h5part/Hdf5.h"

#include <utility>

namespace parafluid::h5
{
class Handle
{
public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer)
    : Id(id)
    , Close(closer)
  {
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept { *this = std::move(other); }
  Handle& operator=(Handle&& other) noexcept
  {
    if (this != &other)
    {
      this->reset();
      this->Id = other.Id;
      this->Close = other.Close;
      other.Id = -1;
    }
    return *this;
  }
  ~Handle() { this->reset(); }
  void reset()
  {
    if (this->Id >= 0 && this->Close)
    {
      this->Close(this->Id);
    }
    this->Id = -1;
  }
  bool valid() const { return this->Id >= 0; }
  hid_t get() const { return this->Id; }
  operator hid_t() const { return this->Id; }

private:
  hid_t Id = -1;
  Closer Close = nullptr;
};

/// Silences HDF5's own error stack printing while alive: the reader reports its own, clearer errors.
class QuietErrors
{
public:
  QuietErrors()
  {
    H5Eget_auto2(H5E_DEFAULT, &this->Function, &this->Data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, this->Function, this->Data); }
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

private:
  H5E_auto2_t Function = nullptr;
  void* Data = nullptr;
};
} // namespace parafluid::h5
