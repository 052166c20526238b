#pragma once
// The process sections' parts of the parser, the validator and the writer (internal to app/document).
#include <QJsonArray>
#include <QJsonObject>
#include <vector>

#include "document/json_reader.h"
#include "document/project.h"

namespace mx::app {

// Reads every process section present in `root` (presence and types; ranges come later).
void readProcessSections(const ObjectReader& root, Project& project);
// The expert keys beyond the core ones: method, simulated_points, rule5_search, grid.modal_candidate_speeds.
void readExpertExtras(const ObjectReader& expert, ExpertSpec& spec);

void validateProcessSections(const Project& project);
void validateExpertExtras(const ExpertSpec& spec);

// Writes the process sections over `root`, which holds the unknown keys (a section absent from the
// project is removed, with its unknown keys).
void putProcessSections(QJsonObject& root, const Project& project);
void putExpertExtras(QJsonObject& expert, const ExpertSpec& spec);

// The part of `original` that `known` (the typed values written back) does not hold, per object.
// The elements of arrays of objects (tools, modes, depth steps, events, chart steps) are left out:
// each keeps its own unknown keys in its struct.
QJsonObject unknownKeys(const QJsonObject& original, const QJsonObject& known);

// Keeps the stored value when it is numerically equal (preserves e.g. 600 vs 600.0 in the file).
void putNumber(QJsonObject& o, const QString& key, double value);
void putOptional(QJsonObject& o, const QString& key, const std::optional<double>& value);
// The array, or no key when absent.
void putNumbers(QJsonObject& o, const QString& key, const std::optional<std::vector<double>>& values);
// `values` as a JSON array, keeping each stored element that is numerically equal.
QJsonArray numbersOver(const QJsonArray& old, const std::vector<double>& values);

}  // namespace mx::app
