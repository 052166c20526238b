#pragma once
// The size limits of the files the application layers read (the engine's readers have their own:
// kPartProgramFileLimit, kFrfFileLimit), and readInputFile for Qt callers. docs/project-file.md lists
// them all.
#include <QByteArray>
#include <QString>

#include "core/input_file.h"

namespace mx::app {

// A project: the examples are under 10 kB; 64 MB is far above any real project and bounds the parse.
inline constexpr InputFileLimit kProjectFileLimit{64 * kMegabyte, "a project file"};
// A tool library (CSV or JSON) of the tool-library editor: at most kMaxTools tools.
inline constexpr InputFileLimit kToolLibraryFileLimit{16 * kMegabyte, "a tool library"};
// A CAM or controller tool library (Fusion 360, FreeCAD, LinuxCNC): a shop's whole library, thousands
// of tools with their holders and presets, a few kB each.
inline constexpr InputFileLimit kCamToolLibraryFileLimit{64 * kMegabyte, "a CAM tool library"};
// Test-cut forces (mean forces per cut, or a dynamometer record of one cut: 1 h at 10 kHz is ~100 MB).
inline constexpr InputFileLimit kTestCutFileLimit{256 * kMegabyte, "a test-cut file"};
// The lobes JSON that millexpert-plot draws.
inline constexpr InputFileLimit kPlotInputFileLimit{64 * kMegabyte, "a lobes JSON file"};

// readInputFile (core/input_file.h) of a Qt path: the bytes, or InvalidInput without the path.
QByteArray readBoundedFile(const QString& path, const InputFileLimit& limit);

}  // namespace mx::app
