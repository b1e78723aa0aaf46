#pragma once
// Reading numpy arrays in place (internal to the Python module): checks of dtype and shape that
// name the argument, and a view of rows of floats with no copy when the array allows it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab::python {

namespace py = pybind11;

/// Rows of `columns` float32 values read in place: row i starts at data + i * row_stride. The
/// leading shape of the array is kept so that answers can take it back ((H, W, 3) rays give
/// (H, W) answers). `owner` keeps the memory alive: the caller's array itself when it could be
/// read in place, else the float32 copy made of it.
struct FloatRows {
  const float* data = nullptr;
  std::ptrdiff_t row_stride = 0;   ///< floats from one row to the next
  std::size_t count = 0;           ///< rows
  std::vector<py::ssize_t> shape;  ///< the array's shape without its last axis
  py::object owner;                ///< what holds the floats
  bool copied = false;             ///< true when the input had to be converted
};

/// `obj` as rows of `columns` floats: any real-number array of shape (..., columns). A float32
/// array whose last axis is contiguous and whose leading axes step regularly (C-contiguous,
/// or a column slice of a wider array such as rays[..., :3]) is read in place; anything else
/// is converted to a float32 copy. Raises TypeError (not a real-number array) or ValueError
/// (wrong last axis), naming `name` and the expected shape.
FloatRows float_rows(py::handle obj, const char* name, int columns);

/// `obj` as a C-contiguous array of dtype T and shape (N, columns) (2-D), read in place when it
/// already is one, else converted (integers of another width, or a non-contiguous array). Raises
/// TypeError or ValueError naming `name` as float_rows does.
template <class T>
py::array_t<T, py::array::c_style> matrix(py::handle obj, const char* name, int columns);

/// A new array of `shape` followed by `trailing` (when not 0), uninitialised. One of
/// kLargeBlockBytes or more lies in a large block (raylab/core/large_block.h: huge pages), freed
/// with the array.
template <class T>
py::array_t<T> new_array(const std::vector<py::ssize_t>& shape, py::ssize_t trailing = 0);

}  // namespace raylab::python
