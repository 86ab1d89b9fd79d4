// meshlab-run: runs a MeshLab filter script (.mlx) on mesh files, headless, for MeshLab
// 2022.02 and later, which have no meshlabserver. It loads MeshLab's stock plugins and any
// installed extra plugins (ours included) through MeshLab's own plugin manager, applies
// the script's filters with the checks MeshLab's GUI makes, and saves the layers asked for.
// The command line is meshlabserver's, so scripts and commands written for it carry over:
//
//   meshlab-run -i scan.ply [more inputs] -s script.mlx [-o out.ply [-l N|x|c] [-m ...]]
//
// No X server is needed (Qt's offscreen platform); filters that need OpenGL are refused
// with MeshLab's own message. Exit status: 0 done, 1 a file or a filter failed, 2 usage.
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/mlapplication.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QStringList>

#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace {

const char* const kUsage =
    "usage: meshlab-run -i INPUT [INPUT...] [-s SCRIPT.mlx] [-o OUTPUT [-l N|x|c] [-m FLAGS...]]...\n"
    "                   [-p PLUGIN_DIR]...\n"
    "Runs a MeshLab filter script on mesh files without a display, as meshlabserver did.\n"
    "  -i  files to open, one layer each, in order (layer 0, 1, ...)\n"
    "  -s  the filter script, e.g. saved from MeshLab's Filters > Show current filter script\n"
    "  -o  after the script, save a layer to this file (the format follows the extension);\n"
    "      -l picks the layer: its number, x for the last, c for the current one (default)\n"
    "  -m  what to save besides positions and faces, as meshlabserver: vc vf vq vn vt vr\n"
    "      (vertex colour, flags, quality, normal, texture coordinate, radius), fc ff fq fn\n"
    "      (face ...), wc wn wt (wedge ...), mp (polygons), sa (ASCII instead of binary)\n"
    "  -p  also load the plugins in this folder (MeshLab's own and its per-user plugin folder\n"
    "      are always loaded)\n"
    "  --list-plugins  list the plugins loaded: name, file and vendor (as Help > Plugin Info),\n"
    "                  and any MeshLab refused, with its reason\n"
    "In a script, a layer parameter's value is a layer number, as with meshlabserver.\n";

struct Output {
    QString file;
    QString layer = "c";  // a layer number, x (last) or c (current)
    int attributes = 0;   // vcg::tri::io::Mask bits
    bool ascii = false;
};

// meshlabserver's -m words.
const std::map<QString, int> kAttributeFlags = {
    {"vc", vcg::tri::io::Mask::IOM_VERTCOLOR},    {"vf", vcg::tri::io::Mask::IOM_VERTFLAGS},
    {"vq", vcg::tri::io::Mask::IOM_VERTQUALITY},  {"vn", vcg::tri::io::Mask::IOM_VERTNORMAL},
    {"vt", vcg::tri::io::Mask::IOM_VERTTEXCOORD}, {"vr", vcg::tri::io::Mask::IOM_VERTRADIUS},
    {"fc", vcg::tri::io::Mask::IOM_FACECOLOR},    {"ff", vcg::tri::io::Mask::IOM_FACEFLAGS},
    {"fq", vcg::tri::io::Mask::IOM_FACEQUALITY},  {"fn", vcg::tri::io::Mask::IOM_FACENORMAL},
    {"wc", vcg::tri::io::Mask::IOM_WEDGCOLOR},    {"wn", vcg::tri::io::Mask::IOM_WEDGNORMAL},
    {"wt", vcg::tri::io::Mask::IOM_WEDGTEXCOORD}, {"mp", vcg::tri::io::Mask::IOM_BITPOLYGONAL},
};

struct Options {
    bool listPlugins = false;
    QStringList inputs;
    QString script;
    std::vector<Output> outputs;
    QStringList pluginDirs;
};

int usageError(const QString& message) {
    std::fprintf(stderr, "meshlab-run: %s\n\n%s", qUtf8Printable(message), kUsage);
    return 2;
}

bool isOption(const QString& argument) { return argument.size() == 2 && argument[0] == '-' && argument[1].isLetter(); }

// meshlabserver's syntax: -i and -m take every following non-option argument.
std::optional<Options> parse(const QStringList& arguments, QString& error) {
    Options options;
    for (int a = 1; a < arguments.size(); ++a) {
        const QString option = arguments[a];
        QStringList values;
        while (a + 1 < arguments.size() && !isOption(arguments[a + 1])) values << arguments[++a];
        if (option == "--list-plugins" && values.isEmpty()) {
            options.listPlugins = true;
        } else if (option == "-i" && !values.isEmpty()) {
            options.inputs << values;
        } else if (option == "-s" && values.size() == 1) {
            options.script = values[0];
        } else if (option == "-o" && values.size() == 1) {
            options.outputs.push_back({values[0]});
        } else if (option == "-l" && values.size() == 1 && !options.outputs.empty()) {
            options.outputs.back().layer = values[0];
        } else if (option == "-m" && !options.outputs.empty() && !values.isEmpty()) {
            for (const QString& word : values) {
                if (word == "sa") {
                    options.outputs.back().ascii = true;
                } else if (kAttributeFlags.count(word)) {
                    options.outputs.back().attributes |= kAttributeFlags.at(word);
                } else {
                    error = QString("unknown -m attribute '%1'").arg(word);
                    return std::nullopt;
                }
            }
        } else if (option == "-p" && values.size() == 1) {
            options.pluginDirs << values[0];
        } else {
            error = QString("unexpected '%1'%2").arg(option, values.isEmpty() ? "" : " " + values.join(' '));
            return std::nullopt;
        }
    }
    if (options.inputs.isEmpty() && !options.listPlugins) {
        error = "no input file (-i)";
        return std::nullopt;
    }
    return options;
}

// A filter's progress, one line per tenth, on stdout beside the log.
bool printProgress(const int percent, const char* what) {
    static int lastTenth = -1;
    const int tenth = percent / 10;
    if (tenth != lastTenth && percent >= 0 && percent <= 100) {
        lastTenth = tenth;
        std::printf("  %3d%% %s\n", percent, what ? what : "");
        std::fflush(stdout);
    }
    return true;
}

// Prints the log entries written since the last call.
void printNewLogLines(const GLLogStream& log, int& printed) {
    QStringList lines;
    log.print(lines);
    for (; printed < lines.size(); ++printed) std::printf("%s\n", qUtf8Printable(lines[printed]));
    std::fflush(stdout);
}

MeshModel* layerAt(MeshDocument& md, int position) {
    int p = 0;
    for (MeshModel& m : md.meshIterator()) {
        if (p++ == position) return &m;
    }
    return nullptr;
}

// The script's values over the filter's own defaults (a value the script does not give
// keeps its default, as in MeshLab's dialog); layer numbers become MeshLab's layer ids.
RichParameterList parametersFor(const QString& filterName, FilterPlugin& plugin, const QAction* action,
                                const RichParameterList& scripted, MeshDocument& md) {
    RichParameterList parameters = plugin.initParameterList(action, md);
    for (const RichParameter& given : scripted) {
        if (!parameters.hasParameter(given.name())) {
            std::printf("Warning: '%s' has no parameter '%s'; ignored.\n", qUtf8Printable(filterName),
                        qUtf8Printable(given.name()));
            continue;
        }
        if (given.stringType() == "RichMesh") {
            const MeshModel* layer = layerAt(md, given.value().getInt());
            if (!layer) {
                throw MLException(QString("'%1' asks for layer %2 as '%3', but only %4 layer(s) are open.")
                                      .arg(filterName)
                                      .arg(given.value().getInt())
                                      .arg(given.name())
                                      .arg(int(md.meshNumber())));
            }
            parameters.setValue(given.name(), IntValue(layer->id()));
        } else {
            parameters.setValue(given.name(), given.value());
        }
    }
    return parameters;
}

void applyFilter(PluginManager& plugins, const QString& filterName, const RichParameterList& scripted,
                 MeshDocument& md) {
    QAction* action = plugins.filterAction(filterName);
    if (!action) throw MLException(QString("No filter named '%1' (is its plugin installed?)").arg(filterName));
    FilterPlugin* plugin = plugins.getFilterPluginFromAction(action);
    if (plugin->requiresGLContext(action)) {
        throw MLException(QString("'%1' needs an OpenGL context, which meshlab-run does not have.").arg(filterName));
    }
    if (plugin->filterArity(action) == FilterPlugin::SINGLE_MESH && md.mm() == nullptr) {
        throw MLException(QString("'%1' needs a layer; none is open.").arg(filterName));
    }
    if (md.mm()) {
        QStringList missing;
        if (!plugin->isFilterApplicable(action, *md.mm(), missing)) {
            throw MLException(QString("'%1' cannot be applied to layer '%2': it needs %3.")
                                  .arg(filterName, md.mm()->label(), missing.join(", ")));
        }
        md.mm()->updateDataMask(plugin->getRequirements(action));
    }
    const RichParameterList parameters = parametersFor(filterName, *plugin, action, scripted, md);
    plugin->setLog(&md.Log);
    unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
    plugin->applyFilter(action, parameters, md, postConditionMask, printProgress);
    for (MeshModel& m : md.meshIterator()) vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
    // What the GUI does after a filter, for the layers to be saved with what it made.
    const int classes = int(plugin->getClass(action));
    if (md.mm()) {
        if (classes & FilterPlugin::FaceColoring) md.mm()->updateDataMask(MeshModel::MM_FACECOLOR);
        if (classes & FilterPlugin::VertexColoring) md.mm()->updateDataMask(MeshModel::MM_VERTCOLOR);
    }
}

// Saves with the attributes asked for (and the format can hold), as meshlabserver did;
// MeshLab's load_save helper would save everything the layer has.
void save(PluginManager& plugins, MeshModel& layer, const Output& output, GLLogStream& log) {
    const QString format = QFileInfo(output.file).suffix().toLower();
    IOPlugin* io = plugins.outputMeshPlugin(format);
    if (!io) throw MLException(QString("Cannot save '%1': MeshLab has no writer for .%2 files.").arg(output.file, format));
    io->setLog(&log);
    int capability = 0, defaultBits = 0;
    io->exportMaskCapability(format, capability, defaultBits);
    RichParameterList parameters = io->initSaveParameter(format, layer);
    if (output.ascii && parameters.hasParameter("Binary")) parameters.setValue("Binary", BoolValue(false));
    const int attributes = output.attributes & capability;
    if (attributes & vcg::tri::io::Mask::IOM_BITPOLYGONAL) layer.updateDataMask(MeshModel::MM_FACEFACETOPO);
    io->save(format, output.file, layer, attributes, parameters, nullptr);
}

MeshModel* outputLayer(MeshDocument& md, const QString& which) {
    if (which == "c") return md.mm();
    if (which == "x") return layerAt(md, int(md.meshNumber()) - 1);
    bool number = false;
    const int position = which.toInt(&number);
    return number ? layerAt(md, position) : nullptr;
}

// MeshLab's plugin folder, its per-user one and the folders given with -p, as MeshLab
// loads them at start-up.
void loadPlugins(PluginManager& plugins, const QStringList& extraDirs) {
    // Installed beside meshlab, MeshLab's own rule finds its plugins; installed elsewhere
    // (~/.local/bin), the folder of the MeshLab it was built for.
    QString systemDir = meshlab::defaultPluginPath();
    if (systemDir.isEmpty() || QDir(systemDir).entryList({"*.so"}, QDir::Files).isEmpty()) {
        systemDir = PCSKELETON_MESHLAB_PLUGIN_DIR;
    }
    std::vector<QDir> dirs = {QDir(systemDir), QDir(MeshLabApplication::extraPluginsLocation())};
    for (const QString& dir : extraDirs) dirs.emplace_back(dir);
    for (const QDir& dir : dirs) {
        try {
            plugins.loadPlugins(dir);
        } catch (const MLException& e) {
            // MeshLab itself goes on without the plugins it could not load; so does this.
            std::fprintf(stderr, "Warning: %s\n", e.what());
        }
    }
}

void listPlugins(const PluginManager& plugins) {
    for (const MeshLabPlugin* plugin : plugins.pluginIterator()) {
        std::printf("%s\t%s\t%s\n", qUtf8Printable(plugin->pluginName()),
                    qUtf8Printable(plugin->pluginFileInfo().absoluteFilePath()), qUtf8Printable(plugin->vendor()));
    }
    std::printf("%d filter plugins\n", int(std::distance(plugins.filterPluginIterator().begin(),
                                                    plugins.filterPluginIterator().end())));
}

int run(const Options& options) {
    PluginManager& plugins = meshlab::pluginManagerInstance();
    loadPlugins(plugins, options.pluginDirs);
    if (options.listPlugins) {
        listPlugins(plugins);
        if (options.inputs.isEmpty()) return 0;
    }

    MeshDocument md;
    int logged = 0;
    try {
        for (const QString& input : options.inputs) {
            if (!QFileInfo(input).isFile()) throw MLException(QString("Cannot open '%1': no such file.").arg(input));
            for (MeshModel* m : meshlab::loadMeshWithStandardParameters(input, md)) {
                std::printf("Mesh %s loaded: %d vertices, %d faces\n", qUtf8Printable(QFileInfo(input).absoluteFilePath()),
                            m->cm.vn, m->cm.fn);
            }
        }
        if (!options.script.isEmpty()) {
            FilterScript script;
            if (!QFileInfo(options.script).isFile() || !script.open(options.script)) {
                throw MLException(QString("Cannot read the filter script '%1': no such file, or not a MeshLab "
                                          "filter script (.mlx).").arg(options.script));
            }
            std::printf("Starting script of %d filter(s)\n", int(script.size()));
            for (const FilterNameParameterValuesPair& step : script) {
                std::printf("filter: %s\n", qUtf8Printable(step.first));
                try {
                    applyFilter(plugins, step.first, step.second, md);
                } catch (const MLException& e) {
                    printNewLogLines(md.Log, logged);
                    throw MLException(QString("Filter '%1' failed: %2").arg(step.first, e.what()));
                }
                printNewLogLines(md.Log, logged);
            }
        }
        for (const Output& output : options.outputs) {
            MeshModel* layer = outputLayer(md, output.layer);
            if (!layer) {
                throw MLException(QString("Cannot save '%1': there is no layer '%2' (%3 layer(s) open).")
                                      .arg(output.file, output.layer)
                                      .arg(int(md.meshNumber())));
            }
            save(plugins, *layer, output, md.Log);
            std::printf("Layer '%s' saved to %s\n", qUtf8Printable(layer->label()), qUtf8Printable(output.file));
        }
    } catch (const MLException& e) {
        printNewLogLines(md.Log, logged);
        std::fprintf(stderr, "meshlab-run: %s\n", e.what());
        return 1;
    }
    printNewLogLines(md.Log, logged);
    return 0;
}

// MeshLab's library prints its own debugging (every log line again, "FilterScript", ...)
// through qDebug: only Qt's warnings and errors reach stderr.
void quietMessages(QtMsgType type, const QMessageLogContext&, const QString& message) {
    if (type == QtDebugMsg || type == QtInfoMsg) return;
    std::fprintf(stderr, "%s\n", qUtf8Printable(message));
}

}  // namespace

int main(int argc, char* argv[]) {
    qInstallMessageHandler(quietMessages);
    // Headless: no X server is needed, and none is opened even when one is there.
    if (!std::getenv("QT_QPA_PLATFORM")) setenv("QT_QPA_PLATFORM", "offscreen", 1);
    QApplication app(argc, argv);
    // Where MeshLab keeps its settings and per-user plugins is named after these.
    QCoreApplication::setOrganizationName(MeshLabApplication::organization());
    QCoreApplication::setApplicationName(MeshLabApplication::appArchitecturalName(
        MeshLabApplication::HW_ARCHITECTURE(QSysInfo::WordSize)));
    std::setlocale(LC_ALL, "C");
    QLocale::setDefault(QLocale::C);

    const QStringList arguments = app.arguments();
    if (arguments.contains("-h") || arguments.contains("--help")) {
        std::printf("%s", kUsage);
        return 0;
    }
    if (arguments.contains("--version")) {
        std::printf("meshlab-run for MeshLab %s\n", meshlab::meshlabVersion().c_str());
        return 0;
    }
    QString error;
    const std::optional<Options> options = parse(arguments, error);
    if (!options) return usageError(error);
    return run(*options);
}
