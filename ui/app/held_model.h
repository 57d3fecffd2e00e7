#pragma once
// The model a walker is inspected against (docs/VIEWER.md, "Models and walkers"). The viewer
// holds one model source — the loaded population, the default model of real walkers, or an
// opened .ewm — and every walker, a population member or a trial the user opened, is
// reconstructed with it. A walker the model has seen is reconstructed with the model
// without its subject (METHOD §4), as population members always were.

#include <filesystem>
#include <memory>
#include <string>

#include "ui/app/document.h"

namespace ew::ui {

struct WalkerModel {
  EigenwalkerModel model;      // every component the source has
  bool member = false;         // the walker's subject is in the held model
  std::string heldOutSubject;  // the model's name of that subject, when a member
};

// The model walker `index` of `doc` is reconstructed with. Throws std::runtime_error when the
// source holds no model yet, or a leave-one-out model cannot be made (fewer than 2 walkers).
WalkerModel modelForWalker(const Document& doc, int index);

// The subject of `model` that `walker` is, or "" when it is none of them: the same subject
// name, the name with a manifest's letter prefix ("SM2014001" for a file's "2014001",
// "CMU07" for "07"), or the same data (its coefficients within 1 mm RMS of a model walker's:
// the trial the model was built from, whatever it is called).
std::string subjectInModel(const EigenwalkerModel& model, const Walker& walker);

// The held model when it is not the loaded population's own (the default model of real
// walkers, an opened .ewm): its walkers, not the population's, are then the reference the gait
// report's band, the snippet prior and the analysis use. Null for the population's model.
const EigenwalkerModel* heldModelOtherThanThePopulations(const Document& doc);

// "walkers.csv (30 walkers)", "24 real walkers (default)", "run.ewm (23 walkers)".
std::string heldModelName(const Document& doc);
// The same in a sentence's words: "the loaded population", "the default model", "run.ewm".
std::string heldModelPhrase(const Document& doc);
// "population", "default", "file".
const char* modelSourceName(ModelSource source);

// The default model of real walkers (core/eigenwalker/default_model.h), named for the header.
// Throws ew::Error when its asset is missing or corrupt.
std::shared_ptr<const SavedModel> readDefaultModel();
// A saved model (core/eigenwalker/model_file.h). Throws ew::Error naming the file.
std::shared_ptr<const SavedModel> readModelFile(const std::filesystem::path& file);
// True for a path ending in .ewm (any case).
bool isModelFile(const std::filesystem::path& path);

}  // namespace ew::ui
