#include "keywords.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <type_traits>
#include <variant>
#include <vector>

#include "resharp/core/errors.h"
#include "resharp/pipeline/option_table.h"

namespace resharp::python {
namespace {

constexpr std::string_view kWeldHelp =
    "weld the arrays first, as the command line does after reading a file: vertices at exactly "
    "the same position become one and unused ones are dropped (for a triangle soup, such as "
    "STL's three points per triangle); the output's first vertices are then the welded ones";
constexpr std::string_view kSegmentationHelp =
    "also return what was detected (result.segmentation): per input vertex and face, the labels "
    "of both segmentations";

bool is_bool(py::handle value) {
    return PyBool_Check(value.ptr()) ||
           py::isinstance(value, py::module_::import("numpy").attr("bool_"));
}

/// int and the numpy integers, not bool.
bool is_integer(py::handle value) {
    return !is_bool(value) &&
           py::isinstance(value, py::module_::import("numbers").attr("Integral"));
}

/// float, int and the numpy numbers, not bool.
bool is_real(py::handle value) {
    return !is_bool(value) && py::isinstance(value, py::module_::import("numbers").attr("Real"));
}

[[noreturn]] void wrong_type(const std::string& keyword, const char* expected, py::handle value) {
    throw py::type_error("restore(): " + keyword + " must be " + expected + ", got " +
                         py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
}

long long integer_value(const std::string& keyword, py::handle value) {
    if (!is_integer(value)) wrong_type(keyword, "an int", value);
    try {
        return py::int_(py::reinterpret_borrow<py::object>(value)).cast<long long>();
    } catch (const py::cast_error&) {
        throw InvalidInput("restore(): " + keyword + " is out of range");
    }
}

void set(const std::string& keyword, const ValueField<double>& f, RestoreOptions& o,
         py::handle value) {
    if (!is_real(value)) wrong_type(keyword, "a number", value);
    f.field(o) = value.cast<double>();
}

void set(const std::string& keyword, const ValueField<int>& f, RestoreOptions& o,
         py::handle value) {
    const long long v = integer_value(keyword, value);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
        throw InvalidInput("restore(): " + keyword + " is out of range");
    }
    f.field(o) = static_cast<int>(v);
}

void set(const std::string& keyword, const ValueField<std::size_t>& f, RestoreOptions& o,
         py::handle value) {
    const long long v = integer_value(keyword, value);
    if (v < 0) throw InvalidInput("restore(): " + keyword + " must not be negative");
    f.field(o) = static_cast<std::size_t>(v);
}

void set(const std::string& keyword, const FlagField& f, RestoreOptions& o, py::handle value) {
    if (!is_bool(value)) wrong_type(keyword, "True or False", value);
    f.field(o) = value.cast<bool>() ? f.when_given : !f.when_given;
}

template <class E>
void set(const std::string& keyword, const ChoiceField<E>& f, RestoreOptions& o, py::handle value) {
    if (!py::isinstance<py::str>(value)) wrong_type(keyword, "a str", value);
    std::string name = value.cast<std::string>();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string names;
    for (const auto& [choice, choice_value] : f.choices) {
        if (choice == name) {
            f.field(o) = choice_value;
            return;
        }
        names += (names.empty() ? "'" : ", '") + std::string(choice) + "'";
    }
    throw InvalidInput("restore(): " + keyword + " must be one of " + names + ", got '" +
                       value.cast<std::string>() + "'");
}

bool flag_keyword(const py::kwargs& keywords, const char* name) {
    if (!keywords.contains(name)) return false;
    const py::handle value = keywords[name];
    if (!is_bool(value)) wrong_type(name, "True or False", value);
    return value.cast<bool>();
}

/// grid=: a number (the pitch) or a sequence of 1 or 4 numbers (the pitch and a grid point);
/// None (the default) has the grid inferred.
std::vector<double> grid_numbers(py::handle value) {
    if (is_real(value)) return {value.cast<double>()};
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
        wrong_type("grid", "a pitch or (pitch, x, y, z)", value);
    std::vector<double> numbers;
    for (py::handle x : value.cast<py::sequence>()) {
        if (!is_real(x)) wrong_type("grid", "numbers", value);
        numbers.push_back(x.cast<double>());
    }
    return numbers;
}

const OptionInfo* find_option(const std::string& keyword) {
    for (const OptionInfo& info : restore_option_table()) {
        if (keyword_name(info.name) == keyword) return &info;
    }
    return nullptr;
}

py::dict describe(std::string_view name, py::object default_value, const char* type,
                  py::object choices, std::string_view help) {
    py::dict entry;
    entry["name"] = name;
    entry["default"] = std::move(default_value);
    entry["type"] = type;
    entry["choices"] = std::move(choices);
    entry["help"] = help;
    return entry;
}

template <class T>
py::dict describe(std::string_view name, std::string_view help, const ValueField<T>& f) {
    RestoreOptions defaults;
    return describe(name, py::cast(f.field(defaults)),
                    std::is_floating_point_v<T> ? "float" : "int", py::none(), help);
}

py::dict describe(std::string_view name, std::string_view help, const FlagField&) {
    return describe(name, py::bool_(false), "bool", py::none(), help);
}

template <class E>
py::dict describe(std::string_view name, std::string_view help, const ChoiceField<E>& f) {
    RestoreOptions defaults;
    py::list choices;
    for (const auto& choice : f.choices) choices.append(py::str(std::string(choice.first)));
    return describe(name, py::str(std::string(choice_name(f, f.field(defaults)))), "str",
                    std::move(choices), help);
}

}  // namespace

std::string keyword_name(std::string_view option_name) {
    std::string name(option_name);
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

RestoreCall parse_keywords(const py::kwargs& keywords) {
    const std::string paper = keyword_name(kPaperOptionName);
    RestoreCall call;
    call.weld = flag_keyword(keywords, "weld");
    call.segmentation = flag_keyword(keywords, "segmentation");
    const bool use_paper = flag_keyword(keywords, paper.c_str());
    for (const auto& [key, value] : keywords) {
        const std::string keyword = py::str(key).cast<std::string>();
        if (keyword == "weld" || keyword == "segmentation" || keyword == paper) continue;
        if (keyword == kGridOptionName) {
            if (!value.is_none()) set_grid(call.options.vertices, grid_numbers(value));
            continue;
        }
        const OptionInfo* info = find_option(keyword);
        if (info == nullptr) {
            throw py::type_error("restore() got an unexpected keyword argument '" + keyword + "'");
        }
        if (use_paper && info->paper_choice) {
            throw InvalidInput("restore(): " + keyword +
                               " cannot be given with paper=True, which sets it to the paper's "
                               "choice");
        }
        std::visit([&](const auto& f) { set(keyword, f, call.options, value); }, info->field);
    }
    if (use_paper) call.options = paper_variant(call.options);
    return call;
}

py::list describe_keywords() {
    py::list entries;
    entries.append(describe("weld", py::bool_(false), "bool", py::none(), kWeldHelp));
    entries.append(
        describe("segmentation", py::bool_(false), "bool", py::none(), kSegmentationHelp));
    entries.append(describe(keyword_name(kPaperOptionName), py::bool_(false), "bool", py::none(),
                            kPaperOptionHelp));
    entries.append(describe(kGridOptionName, py::none(), "tuple", py::none(), kGridOptionHelp));
    for (const OptionInfo& info : restore_option_table()) {
        entries.append(std::visit(
            [&](const auto& f) { return describe(keyword_name(info.name), info.help, f); },
            info.field));
    }
    return entries;
}

}  // namespace resharp::python
