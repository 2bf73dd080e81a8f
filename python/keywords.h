#pragma once
/// The keyword arguments of resharp.restore(): every entry of the option table
/// (resharp/pipeline/option_table.h) under its Python name, and the module's own.

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include "resharp/pipeline/options.h"

namespace resharp::python {

namespace py = pybind11;

/// What one call of resharp.restore() asks for.
struct RestoreCall {
    RestoreOptions options;     ///< paper_variant() already applied when `paper=True`
    bool weld = false;          ///< weld the arrays as a triangle soup first
    bool segmentation = false;  ///< return the segmentation labels (keep_segmentation)
};

/// The Python name of an option: its flag name with '_' for '-' (region-angle: region_angle).
std::string keyword_name(std::string_view option_name);

/// `keywords` as a RestoreCall, starting from the library's defaults.
/// \throws py::type_error for an unknown keyword or a value of the wrong type (a number for a
///         flag, a float for a count); InvalidInput naming the keyword for a negative count, an
///         unknown choice, or an option given together with paper=True that the paper's
///         choices set. Ranges are the library's to check (restore() throws InvalidInput).
RestoreCall parse_keywords(const py::kwargs& keywords);

/// The keywords as the Python package shows them, in table order after weld, segmentation and
/// paper: a list of dicts {name, default, type ("float", "int", "bool" or "str"), choices (a
/// list of str, or None), help}.
py::list describe_keywords();

}  // namespace resharp::python
