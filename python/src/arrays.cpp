// SPDX-License-Identifier: MIT
// numpy arrays to and from the host model's images and fields.
#include <cmath>
#include <string>

#include "bindings.h"

namespace tristream::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// Copies a C-ordered array of `T` into `image`, refusing values that are not integers in 0..255.
template <class T>
void copy_checked(const py::array_t<T, py::array::c_style | py::array::forcecast>& a, Image& image,
                  const std::string& what) {
  const T* v = a.data();
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const double x = double(v[i]);
    if (!(x >= 0 && x <= 255 && std::floor(x) == x)) {
      const std::size_t pixel = i / std::size_t(image.channels);
      throw py::value_error(what + ": pixel (x " + std::to_string(pixel % std::size_t(image.width)) + ", y " +
                            std::to_string(pixel / std::size_t(image.width)) + ") channel " +
                            std::to_string(i % std::size_t(image.channels)) + " is " +
                            py::str(py::float_(x)).cast<std::string>() + "; expected integers 0 to 255 (8-bit images)");
    }
    image.pixels[i] = std::uint8_t(x);
  }
}

}  // namespace

Image image_from_array(const py::handle& handle, const std::string& what) {
  const py::array a = py::array::ensure(handle);
  if (!a) throw py::type_error(what + ": expected a numpy array (or array-like) of pixels");
  const bool shaped = a.ndim() == 2 || (a.ndim() == 3 && (a.shape(2) == 1 || a.shape(2) == 3));
  if (!shaped || a.shape(0) < 1 || a.shape(1) < 1)
    throw py::value_error(what + ": expected an array of shape (H, W), (H, W, 1) or (H, W, 3), found " + shape_text(a));
  const char kind = a.dtype().kind();
  if (kind != 'u' && kind != 'i' && kind != 'f')
    throw py::value_error(what + ": expected an integer or float array, found dtype " +
                          py::str(a.dtype()).cast<std::string>());
  Image image(int(a.shape(1)), int(a.shape(0)), a.ndim() == 3 ? int(a.shape(2)) : 1);
  if (a.dtype().is(py::dtype::of<std::uint8_t>())) {
    const auto c = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(a);
    std::copy(c.data(), c.data() + image.pixels.size(), image.pixels.begin());
  } else if (kind == 'f') {
    copy_checked(py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a), image, what);
  } else {
    copy_checked(py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a), image, what);
  }
  return image;
}

py::array_t<std::uint8_t> array_from_image(const Image& image) {
  std::vector<py::ssize_t> shape{image.height, image.width};
  if (image.channels != 1) shape.push_back(image.channels);
  py::array_t<std::uint8_t> out(shape);
  std::copy(image.pixels.begin(), image.pixels.end(), out.mutable_data());
  return out;
}

py::array_t<double> array_from_field(const Field& field, ColorSpace space) {
  std::vector<py::ssize_t> shape{field.height, field.width};
  if (field.channels != 1) shape.push_back(field.channels);
  py::array_t<double> out(shape);
  double* o = out.mutable_data();
  const std::size_t nc = std::size_t(field.channels);
  for (std::size_t p = 0; p < std::size_t(field.width) * std::size_t(field.height); ++p) {
    const double* f = &field.v[p * nc];
    if (space == ColorSpace::ycbcr) {
      // A pixel outside one layer's domain is outside the picture's (NaN in every channel).
      const bool covered = !std::isnan(f[0]) && !std::isnan(f[1]) && !std::isnan(f[2]);
      const auto rgb = ycbcr_to_rgb(f[0], f[1], f[2]);
      for (std::size_t c = 0; c < 3; ++c) o[p * 3 + c] = covered ? rgb[c] : std::nan("");
    } else {
      std::copy(f, f + nc, o + p * nc);
    }
  }
  return out;
}

Background background_from(const py::handle& value, const std::string& what) {
  auto byte = [&](const py::handle& v) {
    if (!py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v))
      throw py::value_error(what + ": expected integers 0 to 255, found " + py::repr(v).cast<std::string>());
    const long x = v.cast<long>();
    if (x < 0 || x > 255) throw py::value_error(what + ": expected integers 0 to 255, found " + std::to_string(x));
    return std::uint8_t(x);
  };
  if (py::isinstance<py::int_>(value)) return Background(byte(value));
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
    const py::sequence s = value.cast<py::sequence>();
    if (s.size() == 3) return Background(byte(s[0]), byte(s[1]), byte(s[2]));
  }
  throw py::value_error(what + ": expected one value or (R, G, B), each 0 to 255, found " +
                        py::repr(value).cast<std::string>());
}

std::string one_of(const std::string& keyword, const std::string& value, std::initializer_list<const char*> names) {
  std::string list;
  for (const char* n : names) {
    if (value == n) return value;
    if (!list.empty()) list += '|';
    list += n;
  }
  throw py::value_error(keyword + ": expected " + list + ", found '" + value + "'");
}

}  // namespace tristream::python
