#include "arrays.h"

#include <cmath>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include "resharp/core/errors.h"

namespace resharp::python {
namespace {

std::string text(py::handle object) { return py::str(object).cast<std::string>(); }

/// Refuses anything but a (#rows, 3) numpy array of at most kMaxRows rows.
py::array checked_shape(py::handle object, std::string_view name, std::string_view rows) {
    const std::string what =
        std::string(name) + ": expected a numpy array of shape (" + std::string(rows) + ", 3)";
    if (!py::isinstance<py::array>(object)) {
        throw InvalidInput(what + ", got " + text(py::type::handle_of(object).attr("__name__")));
    }
    auto array = py::reinterpret_borrow<py::array>(object);
    if (array.ndim() != 2 || array.shape(1) != 3) {
        throw InvalidInput(what + ", got shape " + text(array.attr("shape")));
    }
    if (static_cast<std::size_t>(array.shape(0)) > kMaxRows) {
        throw InvalidInput(std::string(name) + ": more than " + std::to_string(kMaxRows) + " rows");
    }
    return array;
}

std::string element(std::string_view name, py::ssize_t row, py::ssize_t column) {
    return std::string(name) + "[" + std::to_string(row) + ", " + std::to_string(column) + "]";
}

/// Calls `read` with `array` as an array_t of the first of `Ts` that its dtype is (native byte
/// order only); false if none.
template <class... Ts, class Read>
bool read_as(const py::array& array, Read&& read) {
    return ((py::isinstance<py::array_t<Ts>>(array) &&
             (read(py::reinterpret_borrow<py::array_t<Ts>>(array)), true)) ||
            ...);
}

template <class T>
void read_positions(const py::array_t<T>& array, std::string_view name, std::vector<Vec3>& out) {
    const auto rows = array.template unchecked<2>();
    out.resize(static_cast<std::size_t>(rows.shape(0)));
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
        for (py::ssize_t k = 0; k < 3; ++k) {
            const double x = rows(i, k);
            if (!std::isfinite(x)) {
                throw InvalidInput(element(name, i, k) + " = " + std::to_string(x) +
                                   ": coordinates must be finite");
            }
            out[static_cast<std::size_t>(i)][k] = x;
        }
    }
}

template <class T>
bool is_negative(T v) {
    if constexpr (std::is_signed_v<T>) {
        return v < 0;
    } else {
        return false;
    }
}

template <class T>
void read_triangles(const py::array_t<T>& array, std::string_view name, std::size_t vertex_count,
                    std::vector<Triangle>& out) {
    const auto rows = array.template unchecked<2>();
    out.resize(static_cast<std::size_t>(rows.shape(0)));
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
        for (py::ssize_t k = 0; k < 3; ++k) {
            const T v = rows(i, k);
            // Negative indices are refused, not counted from the end as numpy would.
            if (is_negative(v) || static_cast<std::uint64_t>(v) >= vertex_count) {
                throw InvalidInput(element(name, i, k) + " = " + std::to_string(v) +
                                   ": out of range for " + std::to_string(vertex_count) +
                                   " vertices");
            }
            out[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = static_cast<Index>(v);
        }
    }
}

/// A 1- or 2-dimensional C-ordered array of `Element` over `values`, which the array then owns.
template <class Element, py::ssize_t columns, class Vector>
py::array hand_over(Vector&& values) {
    static_assert(sizeof(typename Vector::value_type) == sizeof(Element) * columns);
    auto owned = std::make_unique<Vector>(std::move(values));
    const auto rows = static_cast<py::ssize_t>(owned->size());
    const auto* data = reinterpret_cast<const Element*>(owned->data());
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<Vector*>(p); });
    owned.release();  // the capsule deletes it from here on
    const auto item = static_cast<py::ssize_t>(sizeof(Element));
    if constexpr (columns == 1) {
        return py::array(py::dtype::of<Element>(), {rows}, {item}, data, owner);
    } else {
        return py::array(py::dtype::of<Element>(), {rows, columns}, {item * columns, item}, data,
                         owner);
    }
}

}  // namespace

std::vector<Vec3> positions_from(py::handle object, std::string_view name) {
    const py::array array = checked_shape(object, name, "#V");
    std::vector<Vec3> positions;
    const auto read = [&](const auto& typed) { read_positions(typed, name, positions); };
    if (!read_as<double, float>(array, read)) {
        throw InvalidInput(std::string(name) + ": expected dtype float32 or float64, got " +
                           text(array.dtype()));
    }
    return positions;
}

std::vector<Triangle> triangles_from(py::handle object, std::string_view name,
                                     std::size_t vertex_count) {
    const py::array array = checked_shape(object, name, "#F");
    std::vector<Triangle> triangles;
    const auto read = [&](const auto& typed) {
        read_triangles(typed, name, vertex_count, triangles);
    };
    if (!read_as<std::int32_t, std::int64_t, std::uint32_t, std::uint64_t>(array, read)) {
        throw InvalidInput(std::string(name) +
                           ": expected dtype int32, int64, uint32 or uint64, got " +
                           text(array.dtype()));
    }
    return triangles;
}

py::array positions_to(std::vector<Vec3>&& positions) {
    return hand_over<double, 3>(std::move(positions));
}

py::array triangles_to(std::vector<Triangle>&& triangles) {
    return hand_over<std::int32_t, 3>(std::move(triangles));
}

py::array indices_to(std::vector<Index>&& indices) {
    // Two's complement (C++20): kNoIndex, all bits set, reads -1 as int32.
    return hand_over<std::int32_t, 1>(std::move(indices));
}

py::array flags_to(std::vector<std::uint8_t>&& flags) {
    return hand_over<bool, 1>(std::move(flags));
}

py::array roles_to(std::vector<BandRole>&& roles) {
    static_assert(std::is_same_v<std::underlying_type_t<BandRole>, std::uint8_t>);
    return hand_over<std::uint8_t, 1>(std::move(roles));
}

}  // namespace resharp::python
