#include "numpy_views.h"

#include <memory>
#include <string>

#include "raylab/core/large_block.h"

namespace raylab::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// `obj` as a numpy array of real numbers, or TypeError naming `name`.
py::array real_array(py::handle obj, const char* name, const std::string& expected) {
  py::array a;
  try {
    a = py::array::ensure(obj);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.dtype().kind() == 'O' || a.dtype().kind() == 'U' || a.dtype().kind() == 'S' || a.dtype().kind() == 'c' ||
      a.dtype().kind() == 'V') {
    throw py::type_error(std::string(name) + ": expected an array of real numbers of shape " + expected + ", got " +
                         std::string(py::str(py::type::of(obj).attr("__name__"))) +
                         (a ? " of dtype " + std::string(py::str(a.dtype())) : std::string()));
  }
  return a;
}

// Whether the leading axes of `a` (all but the last) step regularly, as one axis of rows
// `row_bytes` apart in C order (axes of length 1 may have any stride).
bool regular_rows(const py::array& a, py::ssize_t& row_bytes) {
  row_bytes = 0;
  py::ssize_t rows_inside = 1;  // rows spanned by one step of axis k
  for (py::ssize_t k = a.ndim() - 2; k >= 0; --k) {
    if (a.shape(k) == 1) continue;
    if (row_bytes == 0 && rows_inside == 1) row_bytes = a.strides(k);
    if (a.strides(k) != row_bytes * rows_inside) return false;
    rows_inside *= a.shape(k);
  }
  return true;
}

}  // namespace

FloatRows float_rows(py::handle obj, const char* name, int columns) {
  const std::string expected = "(..., " + std::to_string(columns) + ")";
  py::array a = real_array(obj, name, expected);
  if (a.ndim() < 1 || a.shape(a.ndim() - 1) != columns) {
    throw py::value_error(std::string(name) + ": expected shape " + expected + ", got " + shape_text(a));
  }
  FloatRows rows;
  rows.shape.assign(a.shape(), a.shape() + a.ndim() - 1);
  rows.count = 1;
  for (py::ssize_t d : rows.shape) rows.count *= static_cast<std::size_t>(d);
  py::ssize_t row_bytes = 0;
  const bool in_place = a.dtype().is(py::dtype::of<float>()) && a.strides(a.ndim() - 1) == sizeof(float) &&
                        regular_rows(a, row_bytes) && row_bytes % static_cast<py::ssize_t>(sizeof(float)) == 0;
  if (!in_place) {
    a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!a) throw py::error_already_set();
    row_bytes = columns * static_cast<py::ssize_t>(sizeof(float));
    rows.copied = true;
  }
  rows.data = static_cast<const float*>(a.data());
  rows.row_stride = rows.count > 1 ? row_bytes / static_cast<py::ssize_t>(sizeof(float)) : columns;
  rows.owner = a;
  return rows;
}

template <class T>
py::array_t<T, py::array::c_style> matrix(py::handle obj, const char* name, int columns) {
  const std::string expected = "(N, " + std::to_string(columns) + ")";
  const py::array a = real_array(obj, name, expected);
  if (a.ndim() != 2 || a.shape(1) != columns) {
    throw py::value_error(std::string(name) + ": expected shape " + expected + ", got " + shape_text(a));
  }
  if constexpr (std::is_integral_v<T>) {
    if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u') {
      throw py::type_error(std::string(name) + ": expected an array of integers of shape " + expected + ", got dtype " +
                           std::string(py::str(a.dtype())));
    }
    // Negative indices and indices past 2^32 would wrap in the conversion: refuse them first.
    if (!a.dtype().is(py::dtype::of<T>()) && a.size() > 0) {
      const py::object lo = a.attr("min")(), hi = a.attr("max")();
      if (lo.cast<long long>() < 0 || hi.cast<unsigned long long>() > 0xffffffffull) {
        throw py::value_error(std::string(name) + ": vertex indices must lie in [0, 2^32), got values from " +
                              std::string(py::str(lo)) + " to " + std::string(py::str(hi)));
      }
    }
  }
  auto out = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out) throw py::error_already_set();
  return out;
}

namespace {

// A large block, freed with its owner: a numpy array's base capsule deletes the owner with the
// array.
class LargeBlockOwner {
 public:
  explicit LargeBlockOwner(std::size_t bytes) : m_block(allocate_large_block(bytes)), m_bytes(bytes) {}
  ~LargeBlockOwner() { free_large_block(m_block, m_bytes); }
  LargeBlockOwner(const LargeBlockOwner&) = delete;
  LargeBlockOwner& operator=(const LargeBlockOwner&) = delete;
  void* block() const { return m_block; }

 private:
  void* m_block;
  std::size_t m_bytes;
};

}  // namespace

template <class T>
py::array_t<T> new_array(const std::vector<py::ssize_t>& shape, py::ssize_t trailing) {
  std::vector<py::ssize_t> full = shape;
  if (trailing != 0) full.push_back(trailing);
  std::size_t bytes = sizeof(T);
  for (const py::ssize_t extent : full) bytes *= static_cast<std::size_t>(extent);
  if (!is_large_block(bytes)) return py::array_t<T>(full);
  // The answers of a large query: each call returns new arrays, and numpy's own memory would be
  // faulted in 4 KiB at a time every call (a million rays' answers are 8,000 pages).
  // The owner is released to the capsule only once the capsule exists: if making it throws, the
  // unique_ptr still frees the block.
  auto owner = std::make_unique<LargeBlockOwner>(bytes);
  const py::capsule base(owner.get(), [](void* p) noexcept { delete static_cast<LargeBlockOwner*>(p); });
  T* const data = static_cast<T*>(owner.release()->block());
  return py::array_t<T>(full, data, base);
}

template py::array_t<float, py::array::c_style> matrix<float>(py::handle, const char*, int);
template py::array_t<double, py::array::c_style> matrix<double>(py::handle, const char*, int);
template py::array_t<std::uint32_t, py::array::c_style> matrix<std::uint32_t>(py::handle, const char*, int);
template py::array_t<float> new_array<float>(const std::vector<py::ssize_t>&, py::ssize_t);
template py::array_t<std::int32_t> new_array<std::int32_t>(const std::vector<py::ssize_t>&, py::ssize_t);
template py::array_t<std::uint32_t> new_array<std::uint32_t>(const std::vector<py::ssize_t>&, py::ssize_t);
template py::array_t<bool> new_array<bool>(const std::vector<py::ssize_t>&, py::ssize_t);

}  // namespace raylab::python
