// The Python binding of vcg_ext: numpy arrays in and out, the library's calls one for one.
// No algorithm here. The package around it (python/pcskeleton/__init__.py) adds the
// documentation, the keyword checks' help and the networkx/Open3D conversions.
#include <pcskeleton/curve_skeleton.h>
#include <pcskeleton/core/errors.h>
#include <pcskeleton/editing/skeleton_editing.h>
#include <pcskeleton/io/mesh_io.h>
#include <pcskeleton/io/point_cloud_io.h>
#include <pcskeleton/io/skeleton_io.h>
#include <pcskeleton/reconstruction/skeleton_reconstruction.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
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

std::string keywordOf(Parameter parameter) {
    switch (parameter) {
        case Parameter::NeighbourCount: return "k";
        case Parameter::InitialContractionWeight: return "wl";
        case Parameter::InitialAttractionWeight: return "wh";
        case Parameter::ContractionScale: return "sl";
        case Parameter::MaxContractionWeight: return "max_wl";
        case Parameter::MaxAttractionWeight: return "max_wh";
        case Parameter::LaplacianRowLimit: return "row_limit";
        case Parameter::MaxIterations: return "iterations";
        case Parameter::TerminationThreshold: return "threshold";
        case Parameter::NodeSpacing: return "radius";
        case Parameter::Refinement: return "refine";
        case Parameter::OutlierDetection: return "outlier detection (keep_outliers=True turns it off)";
        case Parameter::OutlierIsolation: return "outlier_isolation";
        case Parameter::OutlierLocalFactor: return "outlier_local";
        case Parameter::OutlierClusterShare: return "outlier_cluster";
        case Parameter::DenoisingPasses: return "denoise";
        case Parameter::LinkLimit: return "link_limit";
        case Parameter::GapLimit: return "gap_limit";
        case Parameter::LoopOpening: return "loop_opening";
        case Parameter::LoopClearance: return "loop_clearance";
        case Parameter::GapStretch: return "gap_stretch";
        case Parameter::ContractedPoints: return "contracted_points";
        case Parameter::Resolution: return "resolution";
        case Parameter::SmoothWeight: return "smooth_weight";
        case Parameter::SurfaceWeight: return "surface_weight";
        case Parameter::SkeletonWeight: return "skeleton_weight";
        case Parameter::OutsideWeight: return "outside_weight";
        case Parameter::OutsideDistance: return "outside_radii";
        case Parameter::SkeletonTopology: return "the topology guarantee (data_topology=True turns it off)";
    }
    return libraryTerms().parameter(parameter);
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

// ---- Parameters: each keyword is one field of the library's parameter structs ----------

struct Settings {
    SkeletonParameters skeleton;
    ReconstructionParameters reconstruction;
};

struct Keyword {
    std::function<py::object(const Settings&)> get;
    std::function<void(Settings&, py::handle)> set;
};

template <class T, class Field>
Keyword field(Field f) {
    return {[f](const Settings& s) { return py::cast(f(const_cast<Settings&>(s))); },
            [f](Settings& s, py::handle v) { f(s) = v.cast<T>(); }};
}
// A keyword that is true when the library's flag is off (keep_outliers = !detect, ...).
template <class Field>
Keyword inverted(Field f) {
    return {[f](const Settings& s) { return py::cast(!f(const_cast<Settings&>(s))); },
            [f](Settings& s, py::handle v) { f(s) = !v.cast<bool>(); }};
}

const std::map<std::string, Keyword>& skeletonKeywords() {
    static const std::map<std::string, Keyword> keywords = {
        {"k", field<int>([](Settings& s) -> int& { return s.skeleton.contraction.neighbourCount; })},
        {"wl", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.initialContractionWeight; })},
        {"wh", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.initialAttractionWeight; })},
        {"sl", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.contractionScale; })},
        {"max_wl", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.maxContractionWeight; })},
        {"max_wh", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.maxAttractionWeight; })},
        {"row_limit", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.laplacianRowLimit; })},
        {"iterations", field<int>([](Settings& s) -> int& { return s.skeleton.contraction.maxIterations; })},
        {"threshold", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.terminationThreshold; })},
        {"denoise", field<int>([](Settings& s) -> int& { return s.skeleton.contraction.denoisingPasses; })},
        {"keep_outliers", inverted([](Settings& s) -> bool& { return s.skeleton.contraction.outliers.detect; })},
        {"outlier_isolation",
         field<double>([](Settings& s) -> double& { return s.skeleton.contraction.outliers.isolationFactor; })},
        {"outlier_local", field<double>([](Settings& s) -> double& { return s.skeleton.contraction.outliers.localFactor; })},
        {"outlier_cluster",
         field<double>([](Settings& s) -> double& { return s.skeleton.contraction.outliers.clusterShare; })},
        {"radius", field<double>([](Settings& s) -> double& { return s.skeleton.thinning.sampleRadius; })},
        {"link_limit", field<double>([](Settings& s) -> double& { return s.skeleton.thinning.linkLimit; })},
        {"gap_limit", field<double>([](Settings& s) -> double& { return s.skeleton.thinning.gapLimit; })},
        {"loop_opening",
         field<double>([](Settings& s) -> double& { return s.skeleton.thinning.narrowLoops.minOpening; })},
        {"loop_clearance",
         field<double>([](Settings& s) -> double& { return s.skeleton.thinning.narrowLoops.minClearance; })},
        {"gap_stretch", field<double>([](Settings& s) -> double& { return s.skeleton.thinning.narrowLoops.gapStretch; })},
        {"extend_tips", field<bool>([](Settings& s) -> bool& { return s.skeleton.thinning.extendTips; })},
        {"refine", field<bool>([](Settings& s) -> bool& { return s.skeleton.thinning.refine; })},
        {"recentre", field<bool>([](Settings& s) -> bool& { return s.skeleton.thinning.recentre; })},
        {"contracted_points",
         {[](const Settings& s) { return py::cast(s.skeleton.resolution.maxContractedPoints); },
          [](Settings& s, py::handle v) {
              const long count = v.cast<long>();
              if (count < 1)
                  throw InvalidInput("contracted_points must be at least 1 (full_resolution=True contracts every point).");
              s.skeleton.resolution.maxContractedPoints = std::size_t(count);
          }}},
        {"full_resolution",
         {[](const Settings& s) { return py::cast(s.skeleton.resolution.maxContractedPoints == 0); },
          [](Settings& s, py::handle v) {
              if (v.cast<bool>()) s.skeleton.resolution.maxContractedPoints = 0;
          }}},
        {"memory_limit",  // GB, as the CLI's --memory-limit; None = 80% of the machine
         {[](const Settings& s) {
              return s.skeleton.resolution.memoryLimit > 0 ? py::cast(s.skeleton.resolution.memoryLimit / 1e9) : py::none();
          },
          [](Settings& s, py::handle v) {
              if (v.is_none()) return;
              const double gigabytes = v.cast<double>();
              if (!(gigabytes > 0) || !std::isfinite(gigabytes))
                  throw InvalidInput("memory_limit must be a positive number of GB.");
              s.skeleton.resolution.memoryLimit = gigabytes * 1e9;
          }}},
    };
    return keywords;
}

const std::map<std::string, Keyword>& reconstructionKeywords() {
    static const std::map<std::string, Keyword> keywords = {
        {"resolution", field<int>([](Settings& s) -> int& { return s.reconstruction.resolution; })},
        {"smooth_weight", field<double>([](Settings& s) -> double& { return s.reconstruction.smoothWeight; })},
        {"surface_weight", field<double>([](Settings& s) -> double& { return s.reconstruction.surfaceWeight; })},
        {"skeleton_weight", field<double>([](Settings& s) -> double& { return s.reconstruction.skeletonWeight; })},
        {"outside_weight", field<double>([](Settings& s) -> double& { return s.reconstruction.outsideWeight; })},
        {"outside_radii", field<double>([](Settings& s) -> double& { return s.reconstruction.outsideRadii; })},
        {"data_topology", inverted([](Settings& s) -> bool& { return s.reconstruction.keepSkeletonTopology; })},
        {"uniform_point_weights", inverted([](Settings& s) -> bool& { return s.reconstruction.adaptToNoise; })},
        {"level_set", inverted([](Settings& s) -> bool& { return s.reconstruction.fitVerticesToPoints; })},
    };
    return keywords;
}

// Applies `kwargs` to the library's defaults: `paper=True` first (the paper's pipeline),
// then every other keyword, so that `paper=True, refine=True` means the paper plus refinement,
// as `--paper --refine` on the CLI. Unknown keywords are a TypeError, as in any Python call.
Settings settingsFrom(const py::dict& kwargs, const std::map<std::string, Keyword>& known, const char* function) {
    Settings s;
    if (kwargs.contains("paper") && kwargs["paper"].cast<bool>()) {
        s.skeleton.keepToThePaper();
        s.reconstruction.keepToThePaper();
    }
    for (const auto& [key, value] : kwargs) {
        const std::string name = key.cast<std::string>();
        if (name == "paper") continue;
        const auto keyword = known.find(name);
        if (keyword == known.end())
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name + "'");
        try {
            keyword->second.set(s, value);
        } catch (const py::cast_error&) {
            throw py::type_error(std::string(function) + "(): " + name + " must be of type " +
                                 std::string(py::str(keyword->second.get(Settings{}).get_type().attr("__name__"))) +
                                 ", got " + std::string(py::str(value.get_type().attr("__name__"))));
        }
    }
    return s;
}

py::dict defaultsOf(const std::map<std::string, Keyword>& keywords) {
    const Settings defaults;
    py::dict d;
    for (const auto& [name, keyword] : keywords) d[name.c_str()] = keyword.get(defaults);
    d["paper"] = false;
    return d;
}

// ---- Arrays ----------------------------------------------------------------------------

PointList pointsFrom(const DoubleArray& array, const char* what) {
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
        case QualityWarning::Kind::Spurs: return "spurs";
        case QualityWarning::Kind::SpuriousCycles: return "spurious_cycles";
        case QualityWarning::Kind::ContactLoops: return "contact_loops";
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
    convergence["stop_reason"] = stopReasonName(q.stopReason);
    convergence["iterations"] = q.iterations;
    convergence["extent_ratio"] = q.extentRatio;
    d["convergence"] = convergence;
    d["node_spacing"] = q.nodeSpacing;
    d["input_points"] = q.inputPoints;
    d["contracted_points"] = q.points;
    d["multi_resolution"] = q.points < q.inputPoints;
    d["outliers"] = q.outliers + q.inputOutliers;
    d["denoising_passes"] = q.denoisingPasses;
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
SkeletonGraph graphFromArrays(const DoubleArray& nodes, const py::object& edges, const py::object& radii,
                              const py::object& correspondence) {
    SkeletonGraph g;
    g.nodes = pointsFrom(nodes, "nodes");
    g.edges = indexRowsFrom<2>(edges, "edges");
    if (!radii.is_none()) {
        const DoubleArray r = radii.cast<DoubleArray>();
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
    PyContraction(const DoubleArray& points, const py::dict& kwargs, const py::object& progress)
        : points_(pointsFrom(points, "points")), settings_(settingsFrom(kwargs, skeletonKeywords(), "Contraction")) {
        checkThinningParameters(settings_.skeleton.thinning);
        withoutGil(progress, [&](const ProgressCallback& callback) {
            work_ = std::make_unique<ContractionInput>(points_, settings_.skeleton.resolution,
                                                       settings_.skeleton.contraction.outliers,
                                                       progressRange(callback, 0, 40));
            contraction_ = std::make_unique<LaplacianContraction>(work_->points(), settings_.skeleton.contraction,
                                                                  progressRange(callback, 40, 100));
            return 0;
        });
    }

    py::dict iterate() {
        const IterationReport r = exclusively([&] { return contraction_->iterate(); });
        py::dict d;
        d["iteration"] = r.iteration;
        d["extent_ratio"] = r.extentRatio;
        d["contraction_weight"] = r.contractionWeight;
        d["seconds"] = r.seconds;
        return d;
    }
    bool finished() const {
        return exclusively([&] { return contraction_->finished(); });
    }
    const char* stopReason() const {
        return stopReasonName(exclusively([&] { return contraction_->stopReason(); }));
    }
    py::array contracted() const {
        return arrayOwning(exclusively([&] { return contraction_->contractedPoints(); }));
    }
    py::array workingPoints() const {
        return arrayOwning(exclusively([&] { return work_->points(); }));
    }

    PySkeleton skeleton(const py::object& progress) const {
        return skeletonFrom(withoutGil(progress, [&](const ProgressCallback& callback) {
            const std::lock_guard<std::mutex> lock(mutex_);
            SkeletonResult result = skeletonFromContraction(*contraction_, settings_.skeleton.thinning, callback);
            work_->carryToAllPoints(result);
            return result;
        }));
    }

private:
    PointList points_;  // ContractionInput refers to it
    Settings settings_;
    std::unique_ptr<ContractionInput> work_;
    std::unique_ptr<LaplacianContraction> contraction_;
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

    m.def("skeleton_defaults", [] { return defaultsOf(skeletonKeywords()); });
    m.def("reconstruction_defaults", [] { return defaultsOf(reconstructionKeywords()); });

    py::class_<PySkeleton>(m, "Skeleton")
        .def(py::init([](const DoubleArray& nodes, const py::object& edges, const py::object& radii,
                         const py::object& correspondence) {
                 PySkeleton s;
                 s.graph = graphFromArrays(nodes, edges, radii, correspondence);
                 return s;
             }),
             py::arg("nodes"), py::arg("edges"), py::arg("radii") = py::none(), py::arg("correspondence") = py::none())
        .def_property_readonly("nodes", [](py::object self) { return viewOf(self, &SkeletonGraph::nodes); })
        .def_property_readonly("edges", [](py::object self) { return viewOf(self, &SkeletonGraph::edges); })
        .def_property_readonly("radii", [](py::object self) { return viewOf(self, &SkeletonGraph::radii); })
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
        .def("__len__", [](const PySkeleton& s) { return s.graph.nodeCount(); });

    m.def("_skeletonize", [](const DoubleArray& points, const py::dict& kwargs, const py::object& progress) {
        const PointList input = pointsFrom(points, "points");
        const Settings settings = settingsFrom(kwargs, skeletonKeywords(), "skeletonize");
        return skeletonFrom(withoutGil(progress, [&](const ProgressCallback& callback) {
            return computeCurveSkeleton(input, settings.skeleton, callback);
        }));
    });

    py::class_<PyContraction>(m, "_Contraction")
        .def(py::init<const DoubleArray&, const py::dict&, const py::object&>())
        .def("iterate", &PyContraction::iterate, "One iteration; returns its report (a dict). Does nothing once finished.")
        .def_property_readonly("finished", &PyContraction::finished)
        .def_property_readonly("stop_reason", &PyContraction::stopReason)
        .def_property_readonly("contracted", &PyContraction::contracted)
        .def_property_readonly("points", &PyContraction::workingPoints)
        .def("_skeleton", &PyContraction::skeleton);

    m.def("_reconstruct", [](const DoubleArray& points, const PySkeleton& skeleton, const py::dict& kwargs,
                             const py::object& progress) {
        const PointList input = pointsFrom(points, "points");
        const Settings settings = settingsFrom(kwargs, reconstructionKeywords(), "reconstruct");
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
    m.def("write_points", [](const DoubleArray& points, const std::string& path) {
        writePointCloud(pointsFrom(points, "points"), path);
    }, py::arg("points"), py::arg("path"));
    m.def("write_mesh", [](const DoubleArray& vertices, const py::object& faces, const std::string& path) {
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
