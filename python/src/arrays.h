// Checks and conversions of numpy arrays passed to the module: each failure is a Python exception that names the
// argument and the rule it broke (TypeError for a wrong type or dtype, ValueError for a shape, order or value).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace softgl_python {

namespace py = pybind11;

/// `obj` as a numpy array, or TypeError naming `arg`.
py::array AsArray(const py::handle& obj, const char* arg);
/// Rows of `cols` floats (shape (N, cols); float32 or float64, C-contiguous, finite), as float32. `min_rows` rows
/// at least.
std::vector<float> FloatRows(const py::handle& obj, const char* arg, int cols, std::size_t min_rows = 0);
/// Rows of `cols` vertex indices (shape (M, cols); any integer dtype, C-contiguous), each in [0, vertices).
std::vector<std::uint32_t> IndexRows(const py::handle& obj, const char* arg, int cols, std::size_t vertices);
/// A 4 x 4 matrix (float32 or float64, finite), row-major as numpy holds it, into glm's column-major form.
glm::mat4 Matrix4(const py::handle& obj, const char* arg);
/// A vector of 3 finite numbers (any sequence or array).
glm::vec3 Vec3(const py::handle& obj, const char* arg);
/// An image: shape (H, W) or (H, W, C) with C in 1 to 4, uint8, C-contiguous; its channel count in `channels`.
py::array ImageArray(const py::handle& obj, const char* arg, int& channels);
/// A finite number > 0 (or >= 0 when `allow_zero`).
float Positive(double value, const char* arg, bool allow_zero = false);
/// The shape as numpy prints it: "(3, 4)".
std::string ShapeText(const py::array& a);

}  // namespace softgl_python
