#pragma once
/// resharp's exceptions as Python exceptions: resharp.Error and its subclasses, each also a
/// subclass of the built-in exception a Python caller would catch (ValueError, OSError).

#include <pybind11/pybind11.h>

namespace resharp::python {

/// Adds Error, InvalidInput, ReadError, ParseError and WriteError to `module` and translates
/// the C++ exceptions of resharp/core/errors.h into them: IoError's path becomes the `path`
/// attribute, ParseError's place the `line` or `byte` attribute (the other is None).
void register_errors(pybind11::module_& module);

}  // namespace resharp::python
