// The Python binding of vcg_ext: numpy arrays in and out, the library's calls one for one.
// No algorithm here. The package around it (python/pcskeleton/__init__.py) adds the
// documentation, the keyword checks' help and the networkx/Open3D conversions.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/parameter_settings.h>
#include <pcskeleton/core/errors.h>
#include <pcskeleton/editing/skeleton_editing.h>
#include <pcskeleton/io/batch_files.h>
#include <pcskeleton/io/mesh_io.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>
#include <pcskeleton/skeleton/skeleton_branches.h>
#include <pcskeleton/version.h>

#include <malloc.h>
#include <omp.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace py = pybind11;
using namespace pcskeleton;

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// ---- Words: the library's advice names this module's keywords -------------------------

// Each parameter by its keyword; a switch whose keyword says the opposite of its words by
// the words and the keyword that turns it off ("outlier detection (keep_outliers=True turns it off)").
std::string keywordOf(Parameter parameter) {
    const ParameterInfo& p = parameterInfo(parameter);
    if (p.type == ValueType::Switch && p.inverted) return std::string(p.words) + " (" + p.name + "=True turns it off)";
    return p.name;
}

std::string stepInPython(Step step) {
    switch (step) {
        case Step::DeleteNodes: return "delete them (SkeletonEditor.delete_nodes)";
        case Step::MergeNodes: return "merge their nodes (SkeletonEditor.merge_nodes)";
        case Step::SetNodeRadii: return "give the skeleton radii (SkeletonEditor.set_radius)";
        case Step::ComputeSkeleton: return "compute the skeleton of these points (pcskeleton.skeletonize)";
        default: return libraryTerms().step(step);
    }
}

const Terms& pythonTerms() {
    static const Terms terms{keywordOf, stepInPython};
    return terms;
}

// The problem in this module's words. A refused keyword leads its sentence as written
// (`resolution must be ...`): Python names are case-sensitive, so it is not capitalised.
std::string messageOf(const Problem& problem) {
    if (!problem.subject) return describe(problem, pythonTerms());
    Problem rest = problem;
    rest.subject.reset();
    return keywordOf(*problem.subject) + " " + describe(rest, pythonTerms());
}

const char* remedyVerb(Remedy::Kind kind) {
    switch (kind) {
        case Remedy::Kind::Raise: return "raise";
        case Remedy::Kind::Lower: return "lower";
        case Remedy::Kind::TurnOn: return "turn_on";
        case Remedy::Kind::TurnOff: return "turn_off";
        case Remedy::Kind::Take: return "take";
    }
    return "";
}

// {"message": ..., "remedies": [("raise", "iterations"), ...]}
py::dict problemDict(const Problem& problem) {
    py::list remedies;
    for (const Remedy& r : problem.remedies) {
        const std::string what = r.kind == Remedy::Kind::Take ? stepInPython(r.step) : keywordOf(r.parameter);
        remedies.append(py::make_tuple(remedyVerb(r.kind), what));
    }
    py::dict d;
    d["message"] = messageOf(problem);
    d["remedies"] = remedies;
    return d;
}

// ---- Parameters: each keyword is one parameter of the library's table ------------------

// The keyword's value as the table takes it; a TypeError for a value of the wrong type (a
// float for an integer, anything but a bool for a switch), as in any Python call.
double keywordValue(const ParameterInfo& p, py::handle value, const char* function) {
    const auto refuse = [&](const char* type) {
        return py::type_error(std::string(function) + "(): " + p.name + " must be of type " + type + ", got " +
                              std::string(py::str(value.get_type().attr("__name__"))));
    };
    // As pybind11 casts them (numpy's scalars included), except that a bool is no number and a
    // float no integer.
    const bool isBool = py::isinstance<py::bool_>(value);
    try {
        switch (p.type) {
            case ValueType::Switch: return value.cast<bool>() ? 1.0 : 0.0;
            case ValueType::Integer: {
                if (isBool || py::isinstance<py::float_>(value)) throw refuse("int");
                PyObject* index = PyNumber_Index(value.ptr());
                if (!index) {
                    PyErr_Clear();
                    throw refuse("int");
                }
                const py::int_ integer = py::reinterpret_steal<py::int_>(index);
                // Out of int's range: the library's own refusal, not a wrap-around.
                if (integer > py::int_(std::numeric_limits<int>::max()) || integer < py::int_(std::numeric_limits<int>::min()))
                    throw InvalidInput(Problem::aboutParameter(p.id, "must be a whole number within int's range."));
                return double(integer.cast<long long>());
            }
            case ValueType::Real:
                if (isBool || py::isinstance<py::str>(value)) throw refuse("float");
                return value.cast<double>();
        }
    } catch (const py::cast_error&) {
        throw refuse(p.type == ValueType::Switch ? "bool" : p.type == ValueType::Integer ? "int" : "float");
    } catch (const py::error_already_set&) {
        throw refuse(p.type == ValueType::Integer ? "int" : "float");
    }
    return 0;
}

py::type_error unexpectedKeyword(const char* function, const std::string& name) {
    return py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
}

// The parameter values of `kwargs`, None meaning "the default" (left out). `accepts(name,
// parameter, value)` sees each keyword first (`parameter` is nullptr for a name that is no
// parameter's): it throws for a keyword the call does not take, and returns false for one it
// has used itself.
template <class Accepts>
std::vector<std::pair<Parameter, double>> parameterValues(const py::dict& kwargs, const char* function,
                                                          const Accepts& accepts) {
    std::vector<std::pair<Parameter, double>> given;
    for (const auto& [key, value] : kwargs) {
        const std::string name = py::cast<std::string>(key);
        const ParameterInfo* p = parameterNamed(name);
        if (!accepts(name, p, value) || value.is_none()) continue;
        given.emplace_back(p->id, keywordValue(*p, value, function));
    }
    return given;
}

// The settings `kwargs` give: `paper=True` first (the paper's pipeline), then every other
// keyword, as the CLI's --paper and its options. Unknown keywords, and keywords of the other
// computation's stage, are a TypeError.
Settings settingsFrom(const py::dict& kwargs, bool reconstruction, const char* function) {
    bool paper = false;
    const auto given = parameterValues(kwargs, function, [&](const std::string& name, const ParameterInfo* p,
                                                             py::handle value) {
        if (name == "paper") {
            if (!py::isinstance<py::bool_>(value)) throw py::type_error(std::string(function) + "(): paper must be of type bool");
            paper = value.cast<bool>();
            return false;
        }
        if (!p || (p->stage == Stage::Reconstruction) != reconstruction) throw unexpectedKeyword(function, name);
        return true;
    });
    return pcskeleton::settingsFrom(paper, given);
}

// {keyword: default} in the table's order, with `paper`.
py::dict defaultsOf(bool reconstruction) {
    py::dict d;
    d["paper"] = false;
    for (const ParameterInfo& p : parameterTable()) {
        if ((p.stage == Stage::Reconstruction) != reconstruction) continue;
        const double value = defaultValue(p.id);
        if (p.type == ValueType::Switch) d[p.name] = value != 0;
        else if (p.type == ValueType::Integer) d[p.name] = (long long)value;
        else d[p.name] = value;
    }
    return d;
}

// {keyword: (help, advanced)} for the package's docstrings.
py::dict helpOf(bool reconstruction) {
    py::dict d;
    for (const ParameterInfo& p : parameterTable()) {
        if ((p.stage == Stage::Reconstruction) == reconstruction) d[p.name] = py::make_tuple(p.help, p.advanced);
    }
    return d;
}

// ---- Arrays ----------------------------------------------------------------------------

// A float64 array of `object`'s numbers: integers and floats, converted as numpy converts
// them. Booleans, complex numbers, strings and Python objects raise TypeError instead of
// being cast (numpy's cast reads True as 1 and drops an imaginary part with only a warning).
DoubleArray realArray(const py::object& object, const char* what) {
    const py::array array = py::array::ensure(object);
    const char kind = array ? array.dtype().kind() : 'O';
    if (kind != 'i' && kind != 'u' && kind != 'f') {
        const std::string got = array && py::isinstance<py::array>(object)
                                    ? "an array of " + std::string(py::str(array.dtype()))
                                    : std::string(py::str(py::type::of(object).attr("__name__")));
        throw py::type_error(std::string(what) + " must be an array of real numbers; got " + got + ".");
    }
    return DoubleArray::ensure(array);
}

PointList pointsFrom(const py::object& object, const char* what) {
    const DoubleArray array = realArray(object, what);
    if (array.ndim() != 2 || array.shape(1) != 3)
        throw InvalidInput(std::string(what) + " must be an array of shape (n, 3); got one of " +
                           std::to_string(array.ndim()) + " dimension(s)" +
                           (array.ndim() == 2 ? " and " + std::to_string(array.shape(1)) + " columns" : "") + ".");
    PointList points(std::size_t(array.shape(0)));
    if (!points.empty()) std::memcpy(points.data()->data(), array.data(), points.size() * 3 * sizeof(double));
    return points;
}

// Indices from any array-like: integers of any width, or floats holding whole numbers,
// each within int's range. (numpy's cast to int would wrap 2^32 + 1 to 1 and cut 1.9 to 1.)
// Returns the values in C order and the array's shape in `shape`.
std::vector<int> indicesFrom(const py::object& object, const char* what, std::vector<py::ssize_t>& shape) {
    const py::array array = py::array::ensure(object);
    if (!array) throw InvalidInput(std::string(what) + " must be an array of integers.");
    shape.assign(array.shape(), array.shape() + array.ndim());
    std::vector<int> indices(std::size_t(array.size()));
    const auto refuse = [&](auto value, const char* why) {
        std::ostringstream text;
        text.precision(17);
        text << what << ": " << value << " is not a valid index (" << why << ").";
        throw InvalidInput(text.str());
    };
    const auto take = [&](auto typed) {
        const auto* values = typed.data();
        for (std::size_t i = 0; i < indices.size(); ++i) {
            const auto value = values[i];
            using Value = std::decay_t<decltype(value)>;
            if constexpr (std::is_floating_point_v<Value>) {
                if (!(value == std::floor(value))) refuse(value, "not a whole number");
            }
            bool inRange = value <= Value(std::numeric_limits<int>::max());
            if constexpr (std::is_signed_v<Value>) inRange = inRange && value >= Value(std::numeric_limits<int>::min());
            if (!inRange) refuse(value, "out of range");
            indices[i] = int(value);
        }
    };
    constexpr auto flags = py::array::c_style | py::array::forcecast;
    switch (array.dtype().kind()) {
        case 'i': take(py::array_t<long long, flags>::ensure(array)); break;
        case 'u': take(py::array_t<unsigned long long, flags>::ensure(array)); break;
        case 'f': take(py::array_t<double, flags>::ensure(array)); break;
        default:
            if (array.size() > 0) throw InvalidInput(std::string(what) + " must be an array of integers.");
    }
    return indices;
}

// Rows of `columns` indices, e.g. edges (e, 2) or faces (f, 3); an empty array is no rows.
template <std::size_t columns>
std::vector<std::array<int, columns>> indexRowsFrom(const py::object& object, const char* what) {
    std::vector<py::ssize_t> shape;
    const std::vector<int> indices = indicesFrom(object, what, shape);
    std::vector<std::array<int, columns>> rows;
    if (indices.empty()) return rows;
    if (shape.size() != 2 || shape[1] != py::ssize_t(columns))
        throw InvalidInput(std::string(what) + " must be an array of shape (n, " + std::to_string(columns) + ").");
    rows.resize(std::size_t(shape[0]));
    std::memcpy(rows.data()->data(), indices.data(), indices.size() * sizeof(int));
    return rows;
}

// A vector of points, index pairs or triples, or numbers, seen by numpy as rows of scalars.
template <class T>
struct Rows {
    using Scalar = std::conditional_t<std::is_same<T, Point>::value, double,
                                      std::conditional_t<std::is_arithmetic<T>::value, T, int>>;
    static constexpr py::ssize_t columns = py::ssize_t(sizeof(T) / sizeof(Scalar));
};

// A numpy array over `values`' storage, kept alive by `base`: (n,) or (n, columns).
template <class T>
py::array arrayOver(const std::vector<T>& values, py::handle base) {
    using Scalar = typename Rows<T>::Scalar;
    const auto* data = reinterpret_cast<const Scalar*>(values.data());
    const auto rows = py::ssize_t(values.size());
    if (Rows<T>::columns == 1) return py::array_t<Scalar>({rows}, data, base);
    return py::array_t<Scalar>({rows, Rows<T>::columns}, data, base);
}

// A numpy array that owns `values` (moved, not copied) through a capsule.
template <class T>
py::array arrayOwning(std::vector<T> values) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return arrayOver(*owned, free);
}

// ---- Batches: one input per process (or Dask worker) -----------------------------------

// glibc's malloc adapts its thresholds to a program's large arrays, unless a threshold is
// fixed in the environment. Dask's worker processes fix one (MALLOC_TRIM_THRESHOLD_=65536,
// to hand memory back to the system early), which also pins the mmap threshold at 128 KiB:
// every large array of a skeletonization is then mapped and unmapped afresh, and an input
// takes markedly longer (docs/benchmarks.md#batches). During one batch input such a process
// gets the upper bounds of glibc's own adaptive thresholds; afterwards its own settings come
// back and the memory is handed back at once.
class BatchInputMemory {
public:
    BatchInputMemory() : fixed_(std::getenv("MALLOC_TRIM_THRESHOLD_") || std::getenv("MALLOC_MMAP_THRESHOLD_")) {
        if (!fixed_) return;
        mallopt(M_MMAP_THRESHOLD, 32 << 20);
        mallopt(M_TRIM_THRESHOLD, 64 << 20);
    }
    ~BatchInputMemory() {
        if (!fixed_) return;
        mallopt(M_MMAP_THRESHOLD, environmentValue("MALLOC_MMAP_THRESHOLD_", 128 << 10));
        mallopt(M_TRIM_THRESHOLD, environmentValue("MALLOC_TRIM_THRESHOLD_", 128 << 10));
        malloc_trim(0);
    }
    BatchInputMemory(const BatchInputMemory&) = delete;
    BatchInputMemory& operator=(const BatchInputMemory&) = delete;

private:
    static int environmentValue(const char* name, int glibcDefault) {
        const char* value = std::getenv(name);
        return value ? std::atoi(value) : glibcDefault;
    }
    bool fixed_;
};

// Runs `work` as one input of a batch: on one OpenMP thread (the batch runs its inputs side
// by side, one per core), with the memory settings above.
py::object asBatchInput(const py::function& work) {
    omp_set_num_threads(1);
    const BatchInputMemory memory;
    return work();
}

// ---- Progress: Python's callback, called with the GIL from the thread that started -------

// A Python exception raised by the callback cannot cross the library (its loops run
// under OpenMP): it is kept, later reports are ignored, and it is raised after the call.
class PythonProgress {
public:
    explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}
    ProgressCallback callback() {
        if (callback_.is_none()) return {};
        return [this](int percent, const char* what) {
            py::gil_scoped_acquire gil;
            if (error_) return;
            try {
                callback_(percent, what);
            } catch (py::error_already_set& e) {
                error_ = std::make_unique<py::error_already_set>(std::move(e));
            }
        };
    }
    void raiseIfFailed() {
        if (error_) throw *error_;
    }

private:
    py::object callback_;
    std::unique_ptr<py::error_already_set> error_;
};

// Runs `work` without the GIL, with Python's progress callback.
template <class Work>
auto withoutGil(const py::object& progress, Work work) {
    PythonProgress python(progress);
    const ProgressCallback callback = python.callback();
    auto result = [&] {
        py::gil_scoped_release released;
        return work(callback);
    }();
    python.raiseIfFailed();
    return result;
}

// ---- The skeleton as Python sees it -----------------------------------------------------

struct PySkeleton {
    SkeletonGraph graph;
    PointList contracted;        // empty when read from a file or edited
    py::object report = py::none();  // a dict, or None
};

// A read-only numpy view of one of the skeleton's arrays, no copy: it keeps the Skeleton
// alive as its base. Read-only because the skeleton's arrays must stay consistent (edit
// through SkeletonEditor, or copy with numpy).
template <class T>
py::array readOnlyView(const py::object& owner, const std::vector<T>& values) {
    py::array view = arrayOver(values, owner);
    view.attr("flags").attr("writeable") = false;
    return view;
}
template <class T>
py::array viewOf(const py::object& self, std::vector<T> SkeletonGraph::*member) {
    return readOnlyView(self, self.cast<const PySkeleton&>().graph.*member);
}

// A numpy array of one value per element of `items`.
template <typename T, typename Item, typename Get>
py::array_t<T> columnOf(const std::vector<Item>& items, Get get) {
    py::array_t<T> column(py::ssize_t(items.size()));
    auto out = column.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < items.size(); ++i) out(py::ssize_t(i)) = T(get(items[i]));
    return column;
}

// The branch table as columns (numpy arrays, one value per branch) and the nodes of each
// branch; each point's branch and place; each node's branch.
py::dict branchesDict(const SkeletonBranches& b) {
    const std::vector<Branch>& t = b.branches;
    py::dict d;
    d["parent"] = columnOf<int>(t, [](const Branch& x) { return x.parent; });
    d["part"] = columnOf<int>(t, [](const Branch& x) { return x.part; });
    d["order"] = columnOf<int>(t, [](const Branch& x) { return x.order; });
    d["base_node"] = columnOf<int>(t, [](const Branch& x) { return x.nodes.front(); });
    d["tip_node"] = columnOf<int>(t, [](const Branch& x) { return x.nodes.back(); });
    d["length"] = columnOf<double>(t, [](const Branch& x) { return x.length; });
    d["chord"] = columnOf<double>(t, [](const Branch& x) { return x.chord; });
    d["base_radius"] = columnOf<double>(t, [](const Branch& x) { return x.baseRadius; });
    d["tip_radius"] = columnOf<double>(t, [](const Branch& x) { return x.tipRadius; });
    d["mean_radius"] = columnOf<double>(t, [](const Branch& x) { return x.meanRadius; });
    d["volume"] = columnOf<double>(t, [](const Branch& x) { return x.volume; });
    d["angle_to_parent"] = columnOf<double>(t, [](const Branch& x) { return x.angleToParent; });
    d["points"] = columnOf<int>(t, [](const Branch& x) { return x.points; });
    d["closes_loop"] = columnOf<bool>(t, [](const Branch& x) { return x.closesLoop; });
    py::list nodes, along, radii;
    for (const Branch& x : t) {
        nodes.append(columnOf<int>(x.nodes, [](int n) { return n; }));
        along.append(columnOf<double>(x.along, [](double v) { return v; }));
        radii.append(columnOf<double>(x.radii, [](double v) { return v; }));
    }
    d["nodes"] = nodes;
    d["profile_along"] = along;
    d["profile_radius"] = radii;
    d["node_branch"] = columnOf<int>(b.nodeBranch, [](int n) { return n; });
    d["point_branch"] = columnOf<int>(b.pointBranch, [](int n) { return n; });
    d["point_position"] = columnOf<double>(b.pointPosition, [](double x) { return x; });
    return d;
}

py::dict topologyDict(const SkeletonTopology& t) {
    py::dict d;
    d["nodes"] = t.nodes;
    d["edges"] = t.edges;
    d["components"] = t.components;
    d["cycles"] = t.cycles;
    d["tips"] = t.tips;
    d["junctions"] = t.junctions;
    d["isolated"] = t.isolated;
    return d;
}

const char* warningKind(QualityWarning::Kind kind) {
    switch (kind) {
        case QualityWarning::Kind::IterationLimit: return "iteration_limit";
        case QualityWarning::Kind::NumericalFailure: return "numerical_failure";
        case QualityWarning::Kind::ManyOutliers: return "many_outliers";
        case QualityWarning::Kind::UncontractedPoints: return "uncontracted_points";
        case QualityWarning::Kind::PartsWithoutBone: return "parts_without_bone";
        case QualityWarning::Kind::IsolatedNodes: return "isolated_nodes";
        case QualityWarning::Kind::NodesOutside: return "nodes_outside";
        case QualityWarning::Kind::NodesAwayFromData: return "nodes_away_from_data";
        case QualityWarning::Kind::Spurs: return "spurs";
        case QualityWarning::Kind::SpuriousCycles: return "spurious_cycles";
        case QualityWarning::Kind::ContactLoops: return "contact_loops";
        case QualityWarning::Kind::FilledLoops: return "filled_loops";
    }
    return "unknown";
}

const char* stopReasonName(StopReason reason) {
    switch (reason) {
        case StopReason::NotStopped: return "not_stopped";
        case StopReason::Converged: return "converged";
        case StopReason::IterationLimit: return "iteration_limit";
        case StopReason::NumericalFailure: return "numerical_failure";
    }
    return "unknown";
}

py::dict reportDict(const SkeletonResult& r) {
    const SkeletonQuality& q = r.quality;
    py::dict d;
    d["topology"] = topologyDict(q.topology);
    py::dict convergence;
    const ContractionOutcome contraction = q.contraction.value_or(ContractionOutcome{});
    convergence["stop_reason"] = stopReasonName(contraction.stopReason);
    convergence["iterations"] = contraction.iterations;
    convergence["extent_ratio"] = contraction.extentRatio;
    d["convergence"] = convergence;
    d["node_spacing"] = q.nodeSpacing;
    d["input_points"] = q.inputPoints;
    d["contracted_points"] = q.points;
    d["multi_resolution"] = q.points < q.inputPoints;
    d["outliers"] = q.outliers + q.inputOutliers;
    d["denoising_passes"] = contraction.denoisingPasses;
    d["sheet_patches"] = q.sheets ? q.sheets->patches : 0;  // flat patches moved onto their medial axes
    // 1-ring neighbours across a gap left out (facing_walls.h); -1 when the facing walls are not separated
    d["facing_neighbours_left_out"] = contraction.facingNeighboursLeftOut;
    // points pulled towards their medial centre (medial_pull.h); -1 when there is no medial pull
    d["medial_pull_points"] = contraction.medialPullPoints;
    py::list warnings;
    for (const QualityWarning& w : q.warnings()) {
        py::dict warning = problemDict(w.problem);
        warning["kind"] = warningKind(w.kind);
        warnings.append(warning);
    }
    d["warnings"] = warnings;
    d["text"] = describe(q, pythonTerms());
    const StageSeconds& s = r.seconds;
    py::dict seconds;
    seconds["subsampling"] = s.subsampling;
    seconds["neighbourhoods"] = s.neighbourhoods;
    seconds["contraction"] = s.contraction;
    seconds["thinning"] = s.thinning;
    seconds["embedding"] = s.embedding;
    seconds["finishing"] = s.finishing;
    d["seconds"] = seconds;
    return d;
}

PySkeleton skeletonFrom(SkeletonResult result) {
    PySkeleton s;
    s.report = reportDict(result);
    s.graph = std::move(result.skeleton);
    s.contracted = std::move(result.contraction.contracted);
    return s;
}

// A skeleton built from arrays (a user's own, or one changed in numpy) must satisfy the
// graph's invariants (invariantViolation), as the editor requires.
SkeletonGraph graphFromArrays(const py::object& nodes, const py::object& edges, const py::object& radii,
                              const py::object& correspondence) {
    SkeletonGraph g;
    g.nodes = pointsFrom(nodes, "nodes");
    g.edges = indexRowsFrom<2>(edges, "edges");
    if (!radii.is_none()) {
        const DoubleArray r = realArray(radii, "radii");
        g.radii.assign(r.data(), r.data() + r.size());
    }
    if (!correspondence.is_none()) {
        std::vector<py::ssize_t> shape;
        g.pointNode = indicesFrom(correspondence, "correspondence", shape);
    }
    // Without radii the graph is checked first (with stand-in radii), then its radii are
    // estimated from the bones, as MeshLab's filters and Edit Skeleton do (fillMissingRadii).
    const bool estimateRadii = g.radii.empty();
    if (estimateRadii) g.radii.assign(g.nodes.size(), 1.0);
    normalizeEdges(g.edges);
    const std::string problem = invariantViolation(g);
    if (!problem.empty()) throw InvalidInput("Not a valid skeleton: " + problem + ".");
    if (estimateRadii) {
        std::fill(g.radii.begin(), g.radii.end(), 0.0);
        fillMissingRadii(g);
    }
    return g;
}

// ---- The step API: a contraction to watch, then its skeleton ----------------------------

class PyContraction {
    mutable std::mutex mutex_;
    // Threads sharing one contraction take turns: the lock is taken without the GIL, so
    // that a call waiting for it never blocks the one holding it (whose progress callback
    // needs the GIL).
    template <class Work>
    auto exclusively(Work work) const {
        const py::gil_scoped_release released;
        const std::lock_guard<std::mutex> lock(mutex_);
        return work();
    }

public:
    PyContraction(const py::object& points, const py::dict& kwargs, const py::object& progress)
        : points_(pointsFrom(points, "points")), settings_(settingsFrom(kwargs, false, "Contraction")) {
        withoutGil(progress, [&](const ProgressCallback& callback) {
            pipeline_ = std::make_unique<SkeletonPipeline>(points_, settings_.skeleton, callback);
            return 0;
        });
    }

    py::dict iterate() {
        const IterationReport r = exclusively([&] { return pipeline_->contraction().iterate(); });
        py::dict d;
        d["iteration"] = r.iteration;
        d["extent_ratio"] = r.extentRatio;
        d["contraction_weight"] = r.contractionWeight;
        d["seconds"] = r.seconds;
        return d;
    }
    bool finished() const {
        return exclusively([&] { return pipeline_->contraction().finished(); });
    }
    const char* stopReason() const {
        return stopReasonName(exclusively([&] { return pipeline_->contraction().stopReason(); }));
    }
    py::array contracted() const {
        return arrayOwning(exclusively([&] { return pipeline_->contraction().contractedPoints(); }));
    }
    py::array workingPoints() const {
        return arrayOwning(exclusively([&] { return pipeline_->input().points(); }));
    }

    // Thinning with the Contraction's parameters, those of `kwargs` (thinning's only) replacing them.
    PySkeleton skeleton(const py::object& progress, const py::dict& kwargs) const {
        const SkeletonGraphParameters graph = thinningSettingsFrom(kwargs).skeleton.graph;
        return skeletonFrom(withoutGil(progress, [&](const ProgressCallback& callback) {
            const std::lock_guard<std::mutex> lock(mutex_);
            return pipeline_->skeleton(graph, callback);
        }));
    }

private:
    // The Contraction's settings with thinning's keywords of `kwargs` instead of its own.
    Settings thinningSettingsFrom(const py::dict& kwargs) const {
        constexpr const char* function = "skeleton_from_contraction";
        const auto given = parameterValues(kwargs, function, [&](const std::string& name, const ParameterInfo* p,
                                                                 py::handle) {
            if (name == "paper" || (p && p->stage != Stage::Thinning && p->stage != Stage::Reconstruction)) {
                throw py::type_error(std::string(function) + "(): '" + name +
                                     "' changes the contraction: give it to Contraction() instead");
            }
            if (!p || p->stage != Stage::Thinning) throw unexpectedKeyword(function, name);
            return true;
        });
        return withParameters(settings_, given);
    }

    PointList points_;  // the pipeline refers to it
    Settings settings_;
    std::unique_ptr<SkeletonPipeline> pipeline_;
};

}  // namespace

PYBIND11_MODULE(_pcskeleton, m) {
    m.doc() = "Curve skeletons of point clouds by Laplacian-based contraction (Cao et al., SMI 2010): "
              "the compiled core of the pcskeleton package.";
    m.attr("__version__") = PCSKELETON_VERSION;

    // The library's refusals are the user's input: ValueError with the library's message.
    // A broken precondition is a bug: RuntimeError naming it as such.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InvalidInput& e) {
            PyErr_SetString(PyExc_ValueError, messageOf(e.problem()).c_str());
        } catch (const CallerError& e) {
            PyErr_SetString(PyExc_RuntimeError, (std::string("pcskeleton internal error: ") + e.what()).c_str());
        }
    });

    m.def("_as_batch_input", &asBatchInput, py::arg("work"));
    m.def("_expand_inputs", &expandInputs, py::arg("arguments"));
    m.def("_output_stems", &outputStems, py::arg("inputs"));
    m.def("_check_skeleton_parameters", [](const py::dict& kwargs, const char* function) {
        settingsFrom(kwargs, false, function);
    });

    m.def("skeleton_defaults", [] { return defaultsOf(false); });
    m.def("reconstruction_defaults", [] { return defaultsOf(true); });
    m.def("skeleton_help", [] { return helpOf(false); });
    m.def("reconstruction_help", [] { return helpOf(true); });

    py::class_<PySkeleton>(m, "Skeleton")
        .def(py::init([](const py::object& nodes, const py::object& edges, const py::object& radii,
                         const py::object& correspondence) {
                 PySkeleton s;
                 s.graph = graphFromArrays(nodes, edges, radii, correspondence);
                 return s;
             }),
             py::arg("nodes"), py::arg("edges"), py::arg("radii") = py::none(), py::arg("correspondence") = py::none())
        .def_property_readonly("nodes", [](py::object self) { return viewOf(self, &SkeletonGraph::nodes); })
        .def_property_readonly("edges", [](py::object self) { return viewOf(self, &SkeletonGraph::edges); })
        .def_property_readonly("radii", [](py::object self) { return viewOf(self, &SkeletonGraph::radii); })
        .def_property_readonly("inferred",
                               [](const PySkeleton& s) {
                                   const std::vector<char> flags = inferredFlags(s.graph);
                                   py::array_t<bool> inferred(py::ssize_t(flags.size()));
                                   auto out = inferred.mutable_unchecked<1>();
                                   for (std::size_t e = 0; e < flags.size(); ++e) out(py::ssize_t(e)) = flags[e] != 0;
                                   return inferred;
                               },
                               "Per edge: True for a bone the data does not show (a gap in the scan bridged).")
        .def_property_readonly("correspondence",
                               [](py::object self) { return viewOf(self, &SkeletonGraph::pointNode); })
        .def_property_readonly("contracted", [](py::object self) -> py::object {
            const PySkeleton& s = self.cast<const PySkeleton&>();
            if (s.contracted.empty()) return py::none();
            return readOnlyView(self, s.contracted);
        })
        .def_readonly("report", &PySkeleton::report)
        .def_property_readonly("topology", [](const PySkeleton& s) { return topologyDict(analyseTopology(s.graph)); })
        .def("write", [](const PySkeleton& s, const std::string& path) { writeSkeleton(s.graph, path); }, py::arg("path"))
        .def("_measure_branches",
             [](const PySkeleton& s, const py::object& up, int root, const py::object& points) {
                 const PointList axis = pointsFrom(up, "up");
                 if (axis.size() != 1) throw InvalidInput("up must be one direction of three numbers, e.g. (0, 0, 1).");
                 BranchOptions options;
                 options.up = axis[0];
                 options.root = root;
                 if (points.is_none()) return branchesDict(measureBranches(s.graph, options));
                 const PointList input = pointsFrom(points, "points");
                 if (input.size() != s.graph.pointNode.size()) {
                     throw InvalidInput("points must be the " + std::to_string(s.graph.pointNode.size()) +
                                        " points the skeleton was computed from, one row each; got " +
                                        std::to_string(input.size()) + ".");
                 }
                 return branchesDict(measureBranches(s.graph, input, options));
             },
             py::arg("up"), py::arg("root"), py::arg("points"))
        .def("__len__", [](const PySkeleton& s) { return s.graph.nodeCount(); })
        // Pickled as copies of its arrays and its report, so that a Skeleton crosses to
        // other processes (a process pool, a Dask cluster) and back exactly.
        .def(py::pickle(
            [](const PySkeleton& s) {
                const SkeletonGraph& g = s.graph;
                const py::object contracted = s.contracted.empty() ? py::object(py::none()) : arrayOwning(s.contracted);
                return py::make_tuple(arrayOwning(g.nodes), arrayOwning(g.edges), arrayOwning(g.radii),
                                      arrayOwning(g.pointNode), arrayOwning(g.inferred), contracted, s.report);
            },
            [](const py::tuple& state) {
                if (state.size() != 7) throw InvalidInput("Not a pickled pcskeleton.Skeleton.");
                PySkeleton s;
                s.graph = graphFromArrays(state[0], state[1], state[2], state[3]);
                s.graph.inferred = indexRowsFrom<2>(state[4], "inferred");
                const std::string problem = invariantViolation(s.graph);  // the inferred bones among the edges
                if (!problem.empty()) throw InvalidInput("Not a valid pickled skeleton: " + problem + ".");
                if (!state[5].is_none()) s.contracted = pointsFrom(state[5], "contracted");
                s.report = state[6];
                return s;
            }));

    m.def("_skeletonize", [](const py::object& points, const py::dict& kwargs, const py::object& progress) {
        const PointList input = pointsFrom(points, "points");
        const Settings settings = settingsFrom(kwargs, false, "skeletonize");
        return skeletonFrom(withoutGil(progress, [&](const ProgressCallback& callback) {
            return computeCurveSkeleton(input, settings.skeleton, callback);
        }));
    });

    py::class_<PyContraction>(m, "_Contraction")
        .def(py::init<const py::object&, const py::dict&, const py::object&>())
        .def("iterate", &PyContraction::iterate, "One iteration; returns its report (a dict). Does nothing once finished.")
        .def_property_readonly("finished", &PyContraction::finished)
        .def_property_readonly("stop_reason", &PyContraction::stopReason)
        .def_property_readonly("contracted", &PyContraction::contracted)
        .def_property_readonly("points", &PyContraction::workingPoints)
        .def("_skeleton", &PyContraction::skeleton, py::arg("progress"), py::arg("parameters"));

    m.def("_reconstruct", [](const py::object& points, const PySkeleton& skeleton, const py::dict& kwargs,
                             const py::object& progress) {
        const PointList input = pointsFrom(points, "points");
        const Settings settings = settingsFrom(kwargs, true, "reconstruct");
        Reconstruction r = withoutGil(progress, [&](const ProgressCallback& callback) {
            return reconstructFromSkeleton(input, skeleton.graph, settings.reconstruction, callback);
        });
        py::dict report;
        report["genus"] = r.report.topology.genus;
        report["components"] = r.report.topology.components;
        report["closed"] = r.report.topology.closedManifold();
        report["topology_controlled"] = r.report.topologyControlled;
        report["converged"] = r.report.converged;
        py::list warnings;
        for (const ReconstructionWarning& w : r.report.warnings) warnings.append(problemDict(w.problem));
        report["warnings"] = warnings;
        report["text"] = describe(r.report, pythonTerms());
        return py::make_tuple(arrayOwning(std::move(r.mesh.vertices)), arrayOwning(std::move(r.mesh.triangles)), report);
    });

    m.def("read_points", [](const std::string& path) {
        PointList points;
        {
            py::gil_scoped_release released;
            points = readPointCloud(path);
        }
        return arrayOwning(std::move(points));
    }, py::arg("path"));
    m.def("read_skeleton", [](const std::string& path) {
        PySkeleton s;
        s.graph = readSkeleton(path);
        return s;
    }, py::arg("path"));
    m.def("write_points", [](const py::object& points, const std::string& path) {
        writePointCloud(pointsFrom(points, "points"), path);
    }, py::arg("points"), py::arg("path"));
    m.def("write_mesh", [](const py::object& vertices, const py::object& faces, const std::string& path) {
        TriangleMesh mesh;
        mesh.vertices = pointsFrom(vertices, "vertices");
        mesh.triangles = indexRowsFrom<3>(faces, "faces");
        for (const auto& triangle : mesh.triangles)
            for (int v : triangle)
                if (v < 0 || std::size_t(v) >= mesh.vertices.size())
                    throw InvalidInput("faces: vertex index " + std::to_string(v) + " out of range.");
        writeTriangleMesh(mesh, path);
    }, py::arg("vertices"), py::arg("faces"), py::arg("path"));

    // Refused edits throw InvalidInput: ValueError, as everywhere.
    py::class_<SkeletonEditor>(m, "SkeletonEditor")
        .def(py::init([](const PySkeleton& s) { return std::make_unique<SkeletonEditor>(s.graph); }), py::arg("skeleton"))
        .def_property_readonly("skeleton",
                               [](const SkeletonEditor& e) {
                                   PySkeleton s;
                                   s.graph = e.skeleton();
                                   return s;
                               })
        .def("move_nodes", [](SkeletonEditor& e, const std::vector<int>& nodes, const std::array<double, 3>& offset) {
            e.moveNodes(nodes, Point(offset[0], offset[1], offset[2]));
        }, py::arg("nodes"), py::arg("offset"))
        .def("delete_nodes", &SkeletonEditor::deleteNodes, py::arg("nodes"))
        .def("delete_edge", &SkeletonEditor::deleteEdge, py::arg("a"), py::arg("b"))
        .def("connect", &SkeletonEditor::connect, py::arg("a"), py::arg("b"))
        .def("merge_nodes", &SkeletonEditor::mergeNodes, py::arg("nodes"))
        .def("split_edge", &SkeletonEditor::splitEdge, py::arg("a"), py::arg("b"), py::arg("at") = 0.5)
        .def("set_radius", &SkeletonEditor::setRadius, py::arg("nodes"), py::arg("radius"))
        .def("scale_radius", &SkeletonEditor::scaleRadius, py::arg("nodes"), py::arg("factor"))
        .def_property_readonly("can_undo", &SkeletonEditor::canUndo)
        .def_property_readonly("can_redo", &SkeletonEditor::canRedo)
        .def_property_readonly("undo_text", &SkeletonEditor::undoText)
        .def_property_readonly("redo_text", &SkeletonEditor::redoText)
        .def("undo", &SkeletonEditor::undo)
        .def("redo", &SkeletonEditor::redo);
}
