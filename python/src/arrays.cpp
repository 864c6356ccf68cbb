#include "arrays.h"

#include <cmath>
#include <cstring>

namespace softgl_python {

namespace {

[[noreturn]] void Fail(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

std::string DtypeText(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

void RequireContiguous(const py::array& a, const char* arg) {
  if (!(a.flags() & py::array::c_style))
    Fail(PyExc_ValueError, std::string(arg) + ": the array must be C-contiguous (numpy.ascontiguousarray makes it so)");
}

void RequireShape(const py::array& a, const char* arg, int cols, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != cols)
    Fail(PyExc_ValueError, std::string(arg) + ": shape must be (N, " + std::to_string(cols) + ") " + what + ", got " +
                               ShapeText(a));
}

}  // namespace

std::string ShapeText(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array AsArray(const py::handle& obj, const char* arg) {
  if (!py::isinstance<py::array>(obj))
    Fail(PyExc_TypeError, std::string(arg) + ": expected a numpy array, got " +
                              py::str(py::type::of(obj).attr("__name__")).cast<std::string>());
  return py::reinterpret_borrow<py::array>(obj);
}

std::vector<float> FloatRows(const py::handle& obj, const char* arg, int cols, std::size_t min_rows) {
  const py::array a = AsArray(obj, arg);
  const bool f32 = a.dtype().is(py::dtype::of<float>()), f64 = a.dtype().is(py::dtype::of<double>());
  if (!f32 && !f64) Fail(PyExc_TypeError, std::string(arg) + ": dtype must be float32 or float64, got " + DtypeText(a));
  RequireShape(a, arg, cols, "of floats");
  RequireContiguous(a, arg);
  const std::size_t rows = std::size_t(a.shape(0)), n = rows * std::size_t(cols);
  if (rows < min_rows)
    Fail(PyExc_ValueError, std::string(arg) + ": at least " + std::to_string(min_rows) + " rows needed, got " +
                               std::to_string(rows));
  std::vector<float> out(n);
  if (f32) std::memcpy(out.data(), a.data(), n * sizeof(float));
  else
    for (std::size_t i = 0; i < n; ++i) out[i] = float(static_cast<const double*>(a.data())[i]);
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(out[i]))
      Fail(PyExc_ValueError, std::string(arg) + ": row " + std::to_string(i / std::size_t(cols)) +
                                 " holds NaN or infinity (or a float64 too large for float32)");
  return out;
}

std::vector<std::uint32_t> IndexRows(const py::handle& obj, const char* arg, int cols, std::size_t vertices) {
  const py::array a = AsArray(obj, arg);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    Fail(PyExc_TypeError, std::string(arg) + ": dtype must be an integer type, got " + DtypeText(a));
  RequireShape(a, arg, cols, "of vertex indices");
  RequireContiguous(a, arg);
  const std::size_t n = std::size_t(a.shape(0)) * std::size_t(cols);
  std::vector<std::uint32_t> out(n);
  const int size = int(a.itemsize());
  for (std::size_t i = 0; i < n; ++i) {
    const auto* p = static_cast<const std::uint8_t*>(a.data()) + i * std::size_t(size);
    std::int64_t v = 0;
    std::uint64_t u = 0;
    switch (size) {
      case 1: kind == 'i' ? v = *reinterpret_cast<const std::int8_t*>(p) : u = *p; break;
      case 2: { std::int16_t s; std::uint16_t t; std::memcpy(&s, p, 2); std::memcpy(&t, p, 2); kind == 'i' ? v = s : u = t; break; }
      case 4: { std::int32_t s; std::uint32_t t; std::memcpy(&s, p, 4); std::memcpy(&t, p, 4); kind == 'i' ? v = s : u = t; break; }
      default: { std::int64_t s; std::uint64_t t; std::memcpy(&s, p, 8); std::memcpy(&t, p, 8); kind == 'i' ? v = s : u = t; break; }
    }
    const bool negative = kind == 'i' && v < 0;
    const std::uint64_t index = kind == 'i' ? std::uint64_t(negative ? 0 : v) : u;
    if (negative || index >= vertices)
      Fail(PyExc_ValueError, std::string(arg) + ": index " + (negative ? std::to_string(v) : std::to_string(index)) +
                                 " in row " + std::to_string(i / std::size_t(cols)) + " is outside the " +
                                 std::to_string(vertices) + " vertices");
    out[i] = std::uint32_t(index);
  }
  return out;
}

glm::mat4 Matrix4(const py::handle& obj, const char* arg) {
  py::array a = py::isinstance<py::array>(obj) ? py::reinterpret_borrow<py::array>(obj)
                                                : py::array(py::module_::import("numpy").attr("asarray")(obj));
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    Fail(PyExc_TypeError, std::string(arg) + ": a 4 x 4 matrix of numbers is needed, got dtype " + DtypeText(a));
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    Fail(PyExc_ValueError, std::string(arg) + ": shape must be (4, 4), got " + ShapeText(a));
  const auto d = py::array_t<double, py::array::forcecast>(a).unchecked<2>();
  glm::mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(d(r, c))) Fail(PyExc_ValueError, std::string(arg) + ": holds NaN or infinity");
      m[c][r] = float(d(r, c));
    }
  return m;
}

glm::vec3 Vec3(const py::handle& obj, const char* arg) {
  py::array a;
  try {
    a = py::array_t<double, py::array::forcecast>(py::module_::import("numpy").attr("asarray")(obj, "float64"));
  } catch (const py::error_already_set&) {
    Fail(PyExc_TypeError, std::string(arg) + ": three numbers are needed");
  }
  if (a.ndim() != 1 || a.shape(0) != 3) Fail(PyExc_ValueError, std::string(arg) + ": three numbers are needed, got shape " + ShapeText(a));
  const auto* d = static_cast<const double*>(a.data());
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(d[i])) Fail(PyExc_ValueError, std::string(arg) + ": holds NaN or infinity");
  return glm::vec3(float(d[0]), float(d[1]), float(d[2]));
}

py::array ImageArray(const py::handle& obj, const char* arg, int& channels) {
  const py::array a = AsArray(obj, arg);
  if (!a.dtype().is(py::dtype::of<std::uint8_t>()))
    Fail(PyExc_TypeError, std::string(arg) + ": dtype must be uint8, got " + DtypeText(a));
  if (!(a.ndim() == 2 || (a.ndim() == 3 && a.shape(2) >= 1 && a.shape(2) <= 4)) || a.shape(0) < 1 || a.shape(1) < 1)
    Fail(PyExc_ValueError, std::string(arg) + ": shape must be (H, W) or (H, W, C) with C 1 to 4 and H, W >= 1, got " +
                               ShapeText(a));
  RequireContiguous(a, arg);
  channels = a.ndim() == 2 ? 1 : int(a.shape(2));
  return a;
}

float Positive(double value, const char* arg, bool allow_zero) {
  if (!std::isfinite(value) || value < 0.0 || (!allow_zero && value == 0.0) || value > 3.0e38)
    Fail(PyExc_ValueError, std::string(arg) + ": must be a finite number " + (allow_zero ? ">= 0" : "> 0") + ", got " +
                               std::to_string(value));
  return float(value);
}

}  // namespace softgl_python
