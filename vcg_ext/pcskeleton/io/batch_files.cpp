#include "pcskeleton/io/batch_files.h"

#include "pcskeleton/core/errors.h"
#include "pcskeleton/io/point_cloud_io.h"

#include <algorithm>
#include <filesystem>
#include <glob.h>
#include <map>
#include <set>

namespace pcskeleton {

namespace fs = std::filesystem;

namespace {

bool isGlob(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

std::vector<std::string> globMatches(const std::string& pattern) {
    glob_t found{};
    std::vector<std::string> files;
    if (glob(pattern.c_str(), 0, nullptr, &found) == 0) {
        for (std::size_t i = 0; i < found.gl_pathc; ++i) {
            if (fs::is_regular_file(found.gl_pathv[i])) files.push_back(found.gl_pathv[i]);
        }
    }
    globfree(&found);
    return files;
}

std::vector<std::string> pointFilesIn(const std::string& folder) {
    std::vector<std::string> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file() && isPointCloudFileName(entry.path().string())) {
            files.push_back(entry.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The last `depth` folder names above `path`, joined by '_' ("b_scans" for /a/b/scans/x.ply, depth 2).
std::string foldersAbove(const std::string& path, std::size_t depth) {
    std::vector<std::string> names;
    fs::path folder = fs::absolute(path).lexically_normal().parent_path();
    for (; names.size() < depth && folder.has_relative_path(); folder = folder.parent_path()) {
        names.insert(names.begin(), folder.filename().string());
    }
    std::string joined;
    for (const std::string& name : names) joined += name + "_";
    return joined;
}

}  // namespace

std::vector<std::string> expandInputs(const std::vector<std::string>& arguments) {
    std::vector<std::string> inputs;
    std::set<std::string> seen;
    for (const std::string& argument : arguments) {
        std::vector<std::string> files;
        if (fs::is_directory(argument)) {
            files = pointFilesIn(argument);
            if (files.empty()) throw InvalidInput("the folder '" + argument + "' holds no point file (.ply, .off, .obj, .xyz, .txt, .pts)");
        } else if (isGlob(argument) && !fs::exists(argument)) {
            files = globMatches(argument);
            if (files.empty()) throw InvalidInput("'" + argument + "' matches no file");
        } else {
            files = {argument};
        }
        for (const std::string& file : files) {
            std::error_code error;
            const fs::path canonical = fs::weakly_canonical(file, error);
            if (seen.insert(error ? file : canonical.string()).second) inputs.push_back(file);
        }
    }
    return inputs;
}

std::vector<std::string> outputStems(const std::vector<std::string>& inputs) {
    std::vector<std::string> stems;
    for (const std::string& input : inputs) stems.push_back(fs::path(input).stem().string());
    std::map<std::string, std::vector<std::size_t>> byStem;
    for (std::size_t i = 0; i < inputs.size(); ++i) byStem[stems[i]].push_back(i);
    for (const auto& [stem, group] : byStem) {
        if (group.size() < 2) continue;
        // Folders first, then the extension too, at the smallest depth that tells them apart.
        bool distinct = false;
        for (bool withExtension : {false, true}) {
            for (std::size_t depth = withExtension ? 0 : 1; depth <= 64 && !distinct; ++depth) {
                std::set<std::string> names;
                for (std::size_t i : group) {
                    std::string extension = fs::path(inputs[i]).extension().string();
                    if (!extension.empty()) extension = "_" + extension.substr(1);
                    names.insert(foldersAbove(inputs[i], depth) + stem + (withExtension ? extension : ""));
                }
                if (names.size() < group.size()) continue;
                distinct = true;
                for (std::size_t i : group) {
                    std::string extension = fs::path(inputs[i]).extension().string();
                    if (!extension.empty()) extension = "_" + extension.substr(1);
                    stems[i] = foldersAbove(inputs[i], depth) + stem + (withExtension ? extension : "");
                }
            }
            if (distinct) break;
        }
    }
    // A told-apart name may still meet another input's own ("a_scan"): number the later ones.
    std::set<std::string> taken;
    for (std::string& stem : stems) {
        const std::string base = stem;
        for (int n = 2; !taken.insert(stem).second; ++n) stem = base + "_" + std::to_string(n);
    }
    return stems;
}

std::string fromPattern(const std::string& pattern, const std::string& stem) {
    std::string name = pattern;
    for (std::size_t at; (at = name.find("{stem}")) != std::string::npos;) name.replace(at, 6, stem);
    return name;
}

}  // namespace pcskeleton
