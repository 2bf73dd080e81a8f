// The compiled half of the `resharp` Python package (python/resharp/__init__.py is the other):
// restore(), read_mesh() and write_mesh() over numpy arrays, with the GIL released while
// resharp works.

#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <utility>
#include <vector>

#include "arrays.h"
#include "errors.h"
#include "keywords.h"
#include "resharp/core/errors.h"
#include "resharp/io/mesh_io.h"
#include "resharp/pipeline/report_json.h"
#include "resharp/pipeline/restore.h"

namespace resharp::python {
namespace {

Mesh mesh_from(py::handle vertices, py::handle faces) {
    Mesh mesh;
    mesh.positions = positions_from(vertices, "vertices");
    mesh.triangles = triangles_from(faces, "faces", mesh.positions.size());
    return mesh;
}

py::object segmentation_to(Segmentation&& s) {
    py::dict labels;
    labels["is_edge_vertex"] = flags_to(std::move(s.is_edge_vertex));
    labels["vertex_patch"] = indices_to(std::move(s.vertex_patch));
    labels["face_patch"] = indices_to(std::move(s.face_patch));
    labels["face_role"] = roles_to(std::move(s.face_role));
    return labels;
}

/// A cancellation callback that turns Ctrl-C into a stop: restore() asks it before each stage,
/// on the calling thread, which takes the GIL back just long enough to run Python's signal
/// handlers. A raised KeyboardInterrupt stays pending and is rethrown once restore() is back.
class InterruptWatch {
public:
    bool interrupted() {
        const py::gil_scoped_acquire locked;
        interrupted_ = interrupted_ || PyErr_CheckSignals() != 0;
        return interrupted_;
    }
    void rethrow_if_interrupted() const {
        if (interrupted_) throw py::error_already_set();
    }

private:
    bool interrupted_ = false;
};

py::dict restore_arrays(py::handle vertices, py::handle faces, const py::kwargs& keywords) {
    RestoreCall call = parse_keywords(keywords);
    call.options.keep_segmentation = call.segmentation;
    InterruptWatch interrupt;
    call.options.stop.cancelled = [&interrupt] { return interrupt.interrupted(); };
    Mesh mesh = mesh_from(vertices, faces);
    std::vector<Index> welded_vertex;
    RestoreResult result;
    {
        const py::gil_scoped_release unlocked;
        if (call.weld) {
            WeldedMesh welded =
                weld_mapped(TriangleSoup{std::move(mesh.positions), std::move(mesh.triangles)});
            mesh = std::move(welded.mesh);
            welded_vertex = std::move(welded.vertex_of_point);
        }
        result = restore(std::move(mesh), call.options);  // nothing reads it after
    }
    interrupt.rethrow_if_interrupted();
    py::dict out;
    out["vertices"] = positions_to(std::move(result.mesh.positions));
    out["faces"] = triangles_to(std::move(result.mesh.triangles));
    out["source_face"] = indices_to(std::move(result.source_face));
    out["welded_vertex"] =
        call.weld ? py::object(indices_to(std::move(welded_vertex))) : py::none();
    out["report"] = report_to_json(result.report).dump();
    out["segmentation"] =
        call.segmentation ? segmentation_to(std::move(result.segmentation)) : py::none();
    return out;
}

py::tuple read_arrays(const std::filesystem::path& path, bool welded) {
    TriangleSoup soup;
    {
        const py::gil_scoped_release unlocked;
        soup = io::read_mesh(path);
        if (welded) {
            Mesh mesh = weld(soup);
            soup = {std::move(mesh.positions), std::move(mesh.triangles)};
        }
    }
    if (soup.points.size() > kMaxRows || soup.triangles.size() > kMaxRows) {
        throw InvalidInput(path.string() + ": more than " + std::to_string(kMaxRows) +
                           " points or triangles");
    }
    return py::make_tuple(positions_to(std::move(soup.points)),
                          triangles_to(std::move(soup.triangles)));
}

void write_arrays(const std::filesystem::path& path, py::handle vertices, py::handle faces,
                  bool ascii) {
    const Mesh mesh = mesh_from(vertices, faces);
    const py::gil_scoped_release unlocked;
    io::write_mesh(path, mesh, {.encoding = ascii ? io::Encoding::Ascii : io::Encoding::Binary});
}

}  // namespace

void define_module(py::module_& module) {
    module.doc() = "The compiled part of the resharp package; use the package (import resharp).";
    module.attr("__version__") = RESHARP_VERSION;
    register_errors(module);
    module.def("restore", &restore_arrays, py::arg("vertices"), py::arg("faces"),
               "resharp.restore()'s work; returns a dict, which the package wraps.");
    module.def("read_mesh", &read_arrays, py::arg("path"), py::arg("weld") = true,
               "resharp.read_mesh()'s work.");
    module.def("write_mesh", &write_arrays, py::arg("path"), py::arg("vertices"), py::arg("faces"),
               py::kw_only(), py::arg("ascii") = false, "resharp.write_mesh()'s work.");
    module.def("keywords", &describe_keywords, "restore()'s keywords, for the package.");
}

}  // namespace resharp::python

PYBIND11_MODULE(_resharp, module) { resharp::python::define_module(module); }
