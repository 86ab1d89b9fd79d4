#include "pcskeleton/parameter_settings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace pcskeleton {

namespace {

constexpr double kBytesPerGigabyte = 1e9;

// The field behind a numeric parameter, in the library's units; nullptr for a switch.
template <class Field>
void visitField(Settings& s, Parameter id, Field&& visit) {
    ContractionParameters& c = s.skeleton.contraction;
    SkeletonGraphParameters& t = s.skeleton.graph;
    ReconstructionParameters& r = s.reconstruction;
    switch (id) {
        case Parameter::NeighbourCount: return visit(c.neighbourCount);
        case Parameter::InitialContractionWeight: return visit(c.initialContractionWeight);
        case Parameter::InitialAttractionWeight: return visit(c.initialAttractionWeight);
        case Parameter::ContractionScale: return visit(c.contractionScale);
        case Parameter::MaxContractionWeight: return visit(c.maxContractionWeight);
        case Parameter::MaxAttractionWeight: return visit(c.maxAttractionWeight);
        case Parameter::LaplacianRowLimit: return visit(c.laplacianRowLimit);
        case Parameter::MaxIterations: return visit(c.maxIterations);
        case Parameter::TerminationThreshold: return visit(c.terminationThreshold);
        case Parameter::MedialPull: return visit(c.medialPull);
        case Parameter::OutlierDetection: return visit(c.outliers.detect);
        case Parameter::OutlierIsolation: return visit(c.outliers.isolationFactor);
        case Parameter::OutlierLocalFactor: return visit(c.outliers.localFactor);
        case Parameter::OutlierClusterShare: return visit(c.outliers.clusterShare);
        case Parameter::DenoisingPasses: return visit(c.denoisingPasses);
        case Parameter::FacingWalls: return visit(c.separateFacingWalls);
        case Parameter::ContractedPoints: return visit(s.skeleton.resolution.maxContractedPoints);
        case Parameter::FullResolution: return visit(s.skeleton.resolution.maxContractedPoints);
        case Parameter::MemoryLimit: return visit(s.skeleton.resolution.memoryLimit);
        case Parameter::NodeSpacing: return visit(t.nodeSpacing);
        case Parameter::ExtendTips: return visit(t.extendTips);
        case Parameter::Sheets: return visit(t.collapseSheets);
        case Parameter::Recentre: return visit(t.recentre);
        case Parameter::Refinement: return visit(t.refine);
        case Parameter::GapLimit: return visit(t.gapLimit);
        case Parameter::LinkLimit: return visit(t.linkLimit);
        case Parameter::LoopOpening: return visit(t.refinementLimits.minOpening);
        case Parameter::LoopClearance: return visit(t.refinementLimits.minClearance);
        case Parameter::GapStretch: return visit(t.refinementLimits.gapStretch);
        case Parameter::MinHole: return visit(t.refinementLimits.minHole);
        case Parameter::Resolution: return visit(r.resolution);
        case Parameter::SmoothWeight: return visit(r.smoothWeight);
        case Parameter::SurfaceWeight: return visit(r.surfaceWeight);
        case Parameter::SkeletonWeight: return visit(r.skeletonWeight);
        case Parameter::OutsideWeight: return visit(r.outsideWeight);
        case Parameter::OutsideDistance: return visit(r.outsideRadii);
        case Parameter::SkeletonTopology: return visit(r.keepSkeletonTopology);
        case Parameter::PointWeights: return visit(r.adaptToNoise);
        case Parameter::VertexFitting: return visit(r.fitVerticesToPoints);
    }
    throw std::logic_error("a parameter the settings do not hold");
}

// The stage's own check, on settings that differ from valid ones in one value at most.
void checkStage(Stage stage, const Settings& s) {
    switch (stage) {
        case Stage::Contraction:
        case Stage::PointCleaning: return checkContractionParameters(s.skeleton.contraction);
        case Stage::Resolution: return checkResolutionParameters(s.skeleton.resolution);
        case Stage::Thinning: return checkSkeletonGraphParameters(s.skeleton.graph);
        case Stage::Reconstruction: return checkReconstructionParameters(s.reconstruction);
    }
}

}  // namespace

Settings Settings::paper() {
    Settings s;
    s.skeleton.keepToThePaper();
    s.reconstruction.keepToThePaper();
    return s;
}

double parameterValue(const Settings& settings, Parameter id) {
    const ParameterInfo& info = parameterInfo(id);
    double value = 0;
    visitField(const_cast<Settings&>(settings), id, [&](const auto& field) { value = double(field); });
    if (id == Parameter::FullResolution) return value == 0 ? 1.0 : 0.0;
    if (id == Parameter::MemoryLimit) return value / kBytesPerGigabyte;
    if (info.inverted) return value != 0 ? 0.0 : 1.0;
    return value;
}

void setParameter(Settings& settings, Parameter id, double value) {
    const ParameterInfo& info = parameterInfo(id);
    if (info.type == ValueType::Integer &&
        !(value == std::floor(value) && std::abs(value) <= double(std::numeric_limits<int>::max()))) {
        throw InvalidInput(Problem::aboutParameter(id, "must be a whole number."));
    }
    if (info.type == ValueType::Switch && value != 0 && value != 1) {
        throw InvalidInput(Problem::aboutParameter(id, "must be on or off."));
    }
    const bool on = value != 0;
    // The library's value of the field.
    double field = value;
    if (info.type == ValueType::Switch) field = on != info.inverted ? 1.0 : 0.0;
    if (id == Parameter::MemoryLimit) field = value * kBytesPerGigabyte;
    if (id == Parameter::FullResolution) {
        // Off after the paper's pipeline: back to the default subsample.
        const std::size_t current = settings.skeleton.resolution.maxContractedPoints;
        field = on ? 0.0 : double(current == 0 ? ResolutionParameters{}.maxContractedPoints : current);
    }
    // 0 would be the library's full resolution, which has its own switch: as a number of
    // contracted points it is too few, and the stage's check below says so.
    if (id == Parameter::ContractedPoints && field < 1) field = 1;
    // The stage's check sees the value in settings that are otherwise the defaults.
    Settings trial;
    visitField(trial, id, [&](auto& f) { f = static_cast<std::decay_t<decltype(f)>>(field); });
    checkStage(info.stage, trial);
    visitField(settings, id, [&](auto& f) { f = static_cast<std::decay_t<decltype(f)>>(field); });
}

Settings settingsFrom(bool paper, const std::vector<std::pair<Parameter, double>>& given) {
    return withParameters(paper ? Settings::paper() : Settings{}, given);
}

Settings withParameters(Settings settings, const std::vector<std::pair<Parameter, double>>& given) {
    // In the table's order, so that the order of the options does not matter (full
    // resolution, after the number of contracted points, wins over it).
    const std::vector<ParameterInfo>& table = parameterTable();
    for (const ParameterInfo& info : table) {
        for (const auto& [id, value] : given) {
            if (id == info.id) setParameter(settings, id, value);
        }
    }
    return settings;
}

}  // namespace pcskeleton
