#include "errors.h"

#include <string>

#include "resharp/core/errors.h"

namespace resharp::python {
namespace {

namespace py = pybind11;

/// The Python classes, created once per interpreter. Kept for the interpreter's lifetime
/// (extension modules are never unloaded), so the translator may use them at any time.
struct ErrorClasses {
    PyObject* error = nullptr;
    PyObject* invalid_input = nullptr;
    PyObject* read_error = nullptr;
    PyObject* parse_error = nullptr;
    PyObject* write_error = nullptr;
};
ErrorClasses classes;

PyObject* add_class(py::module_& module, const char* name, const char* doc, py::tuple bases) {
    const std::string qualified = std::string("resharp.") + name;
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
    if (type == nullptr) throw py::error_already_set();
    module.attr(name) = py::handle(type);
    return type;  // the new reference is the one `classes` keeps
}

/// Raises an instance of `type` with `message`, and `path`, `line` and `byte` attributes for
/// file errors.
void raise(PyObject* type, const char* message, const IoError* io = nullptr) {
    py::object error = py::reinterpret_borrow<py::object>(type)(message);
    if (io != nullptr) {
        error.attr("path") = io->path();
        const auto* parse = dynamic_cast<const ParseError*>(io);
        const bool is_line = parse && parse->location().kind == FileLocation::Kind::Line;
        const bool is_byte = parse && parse->location().kind == FileLocation::Kind::Byte;
        error.attr("line") = is_line ? py::cast(parse->location().value) : py::none();
        error.attr("byte") = is_byte ? py::cast(parse->location().value) : py::none();
    }
    PyErr_SetObject(type, error.ptr());
}

void translate(std::exception_ptr thrown) {
    try {
        std::rethrow_exception(thrown);
    } catch (const ParseError& e) {
        raise(classes.parse_error, e.what(), &e);
    } catch (const WriteError& e) {
        raise(classes.write_error, e.what(), &e);
    } catch (const IoError& e) {
        raise(classes.read_error, e.what(), &e);
    } catch (const InvalidInput& e) {
        raise(classes.invalid_input, e.what());
    } catch (const Error& e) {
        raise(classes.error, e.what());
    }
}

}  // namespace

void register_errors(py::module_& module) {
    const py::handle exception(PyExc_Exception);
    const py::handle value_error(PyExc_ValueError);
    const py::handle os_error(PyExc_OSError);
    classes.error =
        add_class(module, "Error", "Base of every resharp error.", py::make_tuple(exception));
    const py::handle error(classes.error);
    classes.invalid_input = add_class(
        module, "InvalidInput",
        "The mesh, an array or an option cannot be processed: wrong shape or dtype, NaN, an index "
        "out of range, no triangles, an option out of range. The message names the array and "
        "element or the option.",
        py::make_tuple(error, value_error));
    classes.read_error = add_class(
        module, "ReadError",
        "A mesh file could not be read (missing, unreadable, unknown extension); `path` names it.",
        py::make_tuple(error, os_error));
    classes.parse_error = add_class(
        module, "ParseError",
        "A mesh file is malformed; `path` names it and `line` (text formats) or `byte` (binary "
        "formats) the place, as the message does.",
        py::make_tuple(py::handle(classes.read_error), value_error));
    classes.write_error = add_class(
        module, "WriteError",
        "A mesh file could not be written; `path` names it. No partial file is left there.",
        py::make_tuple(error, os_error));
    py::register_exception_translator(&translate);
}

}  // namespace resharp::python
