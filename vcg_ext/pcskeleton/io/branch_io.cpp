#include "pcskeleton/io/branch_io.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/internal/counted.h"
#include "pcskeleton/io/input_file.h"

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <ostream>
#include <sstream>

namespace pcskeleton {

namespace {

struct Column {
    const char* name;
    std::function<void(std::ostream&, const Branch&, std::size_t)> write;  // a NaN is written as none
};

// Writes a number, or `none` for NaN.
void number(std::ostream& out, double value, const char* none) {
    if (std::isnan(value)) out << none;
    else out << value;
}

// A list of numbers: space-separated in a CSV cell, an array in JSON.
void numbers(std::ostream& out, const std::vector<double>& values, bool json) {
    out << (json ? "[" : "");
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? (json ? ", " : " ") : "") << values[i];
    out << (json ? "]" : "");
}

std::vector<Column> columns(const char* none, bool json) {
    return {
        {"branch", [](std::ostream& o, const Branch&, std::size_t i) { o << i; }},
        {"parent", [](std::ostream& o, const Branch& b, std::size_t) { o << b.parent; }},
        {"order", [](std::ostream& o, const Branch& b, std::size_t) { o << b.order; }},
        {"base_node", [](std::ostream& o, const Branch& b, std::size_t) { o << b.nodes.front(); }},
        {"tip_node", [](std::ostream& o, const Branch& b, std::size_t) { o << b.nodes.back(); }},
        {"nodes", [](std::ostream& o, const Branch& b, std::size_t) { o << b.nodes.size(); }},
        {"length", [](std::ostream& o, const Branch& b, std::size_t) { o << b.length; }},
        {"chord", [](std::ostream& o, const Branch& b, std::size_t) { o << b.chord; }},
        {"base_radius", [](std::ostream& o, const Branch& b, std::size_t) { o << b.baseRadius; }},
        {"tip_radius", [](std::ostream& o, const Branch& b, std::size_t) { o << b.tipRadius; }},
        {"mean_radius", [](std::ostream& o, const Branch& b, std::size_t) { o << b.meanRadius; }},
        {"volume", [](std::ostream& o, const Branch& b, std::size_t) { o << b.volume; }},
        {"angle_to_parent", [none](std::ostream& o, const Branch& b, std::size_t) { number(o, b.angleToParent, none); }},
        {"points", [](std::ostream& o, const Branch& b, std::size_t) { o << b.points; }},
        {"closes_loop", [](std::ostream& o, const Branch& b, std::size_t) { o << (b.closesLoop ? "true" : "false"); }},
        {"part", [](std::ostream& o, const Branch& b, std::size_t) { o << b.part; }},
        {"profile_along", [json](std::ostream& o, const Branch& b, std::size_t) { numbers(o, b.along, json); }},
        {"profile_radius", [json](std::ostream& o, const Branch& b, std::size_t) { numbers(o, b.radii, json); }},
    };
}

}  // namespace

bool isBranchTableFileName(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == "csv" || ext == "json";
}

void writeBranchTable(const SkeletonBranches& branches, const std::string& path) {
    if (!isBranchTableFileName(path)) {
        throw InvalidInput("Cannot write '" + path + "': branch tables are written as .csv or .json.");
    }
    const bool json = extensionOf(path) == "json";
    const std::vector<Column> table = columns(json ? "null" : "", json);
    writeFileAtomically(path, [&](const std::string& temporary) {
        writeTextFile(temporary, [&](std::ostream& out) {
            if (!json) {
                for (std::size_t c = 0; c < table.size(); ++c) out << (c ? "," : "") << table[c].name;
                out << '\n';
            } else {
                out << "[";
            }
            for (std::size_t b = 0; b < branches.branches.size(); ++b) {
                if (json) out << (b ? ",\n " : "\n ") << "{";
                for (std::size_t c = 0; c < table.size(); ++c) {
                    if (json) out << (c ? ", " : "") << '"' << table[c].name << "\": ";
                    else if (c) out << ',';
                    table[c].write(out, branches.branches[b], b);
                }
                out << (json ? "}" : "\n");
            }
            if (json) out << "\n]\n";
        });
    });
}

void writePointBranches(const SkeletonBranches& branches, const std::string& path) {
    if (extensionOf(path) != "csv") {
        throw InvalidInput("Cannot write '" + path + "': the branch of each point is written as .csv.");
    }
    writeFileAtomically(path, [&](const std::string& temporary) {
        writeTextFile(temporary, [&](std::ostream& out) {
            out << "branch,position\n";
            for (std::size_t i = 0; i < branches.pointBranch.size(); ++i) {
                out << branches.pointBranch[i] << ',';
                number(out, branches.pointPosition[i], "");
                out << '\n';
            }
        });
    });
}

std::string describeBranchesOf(const SkeletonBranches& branches, const std::vector<int>& nodes) {
    std::set<int> on;
    for (int n : nodes) {
        if (n >= 0 && std::size_t(n) < branches.nodeBranch.size() && branches.nodeBranch[std::size_t(n)] >= 0) {
            on.insert(branches.nodeBranch[std::size_t(n)]);
        }
    }
    if (on.empty()) return "";
    std::ostringstream text;
    text.precision(6);
    if (on.size() == 1) {
        const Branch& b = branches.branches[std::size_t(*on.begin())];
        text << "branch " << *on.begin() << ": order " << b.order << ", " << b.length << " long, radius "
             << b.baseRadius << " at the base and " << b.tipRadius << " at the tip";
    } else {
        double length = 0.0;
        for (int b : on) length += branches.branches[std::size_t(b)].length;
        text << on.size() << " branches, " << length << " long in all";
    }
    return text.str();
}

std::string describe(const SkeletonBranches& branches) {
    struct Totals {
        std::size_t count = 0;
        double length = 0.0, volume = 0.0;
    };
    std::map<int, std::size_t> perOrder;
    std::map<int, Totals> perPart;
    Totals all;
    for (const Branch& b : branches.branches) {
        ++perOrder[b.order];
        for (Totals* t : {&all, &perPart[b.part]}) ++t->count, t->length += b.length, t->volume += b.volume;
    }
    std::ostringstream text;
    text.precision(6);
    text << counted(all.count, "branch", "branches");
    if (!perOrder.empty()) {
        text << " (";
        for (auto it = perOrder.begin(); it != perOrder.end(); ++it) {
            text << (it == perOrder.begin() ? "" : ", ") << "order " << it->first << ": " << it->second;
        }
        text << ")";
    }
    text << ", " << all.length << " long in all, volume " << all.volume;
    if (perPart.size() > 1) {
        constexpr std::size_t kPartsListed = 10;  // the table's part column has them all
        text << "; in " << perPart.size() << " parts";
        std::size_t listed = 0;
        for (const auto& [part, t] : perPart) {
            if (listed++ == kPartsListed) {
                text << ", ...";
                break;
            }
            text << (listed == 1 ? ": " : ", ") << "part " << part << " " << counted(t.count, "branch", "branches") << ", "
                 << t.length << " long, volume " << t.volume;
        }
    }
    return text.str();
}

}  // namespace pcskeleton
