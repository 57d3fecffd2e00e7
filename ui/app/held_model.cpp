#include "ui/app/held_model.h"

#include <stdexcept>

#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/model_membership.h"
#include "core/eigenwalker/model_file.h"

namespace ew::ui {

std::string subjectInModel(const EigenwalkerModel& model, const Walker& walker) {
  return ew::subjectInModel(model, walker.subject, walker.fit.w);
}

WalkerModel modelForWalker(const Document& doc, int index) {
  const Walker* walker = doc.walkerAt(index);
  if (!walker) throw std::runtime_error("no walker " + std::to_string(index));
  const EigenwalkerModel* held = doc.heldModel();
  if (!held) throw std::runtime_error("the model is not ready yet");
  WalkerModel out;
  out.heldOutSubject = doc.modelSource == ModelSource::Population && !doc.isInspected(index)
                           ? walker->subject
                           : subjectInModel(*held, *walker);
  out.member = !out.heldOutSubject.empty();
  if (!out.member) {
    out.model = *held;
  } else if (doc.modelSource == ModelSource::Population) {
    const auto it = doc.models->withoutSubject.find(out.heldOutSubject);
    if (it == doc.models->withoutSubject.end())
      throw std::runtime_error("no leave-one-out model for " + out.heldOutSubject);
    out.model = it->second;
  } else {
    out.model = modelWithoutSubject(*held, out.heldOutSubject);
  }
  return out;
}

const char* modelSourceName(ModelSource source) {
  switch (source) {
    case ModelSource::Population:
      return "population";
    case ModelSource::Default:
      return "default";
    case ModelSource::File:
      return "file";
  }
  return "population";
}

const EigenwalkerModel* heldModelOtherThanThePopulations(const Document& doc) {
  return doc.modelSource != ModelSource::Population ? doc.heldModel() : nullptr;
}

std::string heldModelPhrase(const Document& doc) {
  switch (doc.modelSource) {
    case ModelSource::Population:
      return "the loaded population";
    case ModelSource::Default:
      return "the default model";
    case ModelSource::File:
      if (doc.modelFile >= 0 && doc.modelFile < static_cast<int>(doc.modelFiles.size()))
        return doc.modelFiles[static_cast<std::size_t>(doc.modelFile)]->name;
      return "no model file";
  }
  return "";
}

std::string heldModelName(const Document& doc) {
  switch (doc.modelSource) {
    case ModelSource::Population:
      return doc.population ? doc.population->label + " (" +
                                  std::to_string(doc.population->walkerCount()) + " walkers)"
                            : "no population loaded";
    case ModelSource::Default:
      return doc.defaultModel ? doc.defaultModel->name : "the default model (not read)";
    case ModelSource::File:
      if (doc.modelFile >= 0 && doc.modelFile < static_cast<int>(doc.modelFiles.size())) {
        const auto& m = *doc.modelFiles[static_cast<std::size_t>(doc.modelFile)];
        return m.name + " (" + std::to_string(m.model.walkerCount()) + " walkers)";
      }
      return "no model file";
  }
  return "";
}

std::shared_ptr<const SavedModel> readDefaultModel() {
  auto saved = std::make_shared<SavedModel>();
  saved->model = defaultRealModel();
  saved->name = defaultRealModelName();
  if (saved->name.find("default") == std::string::npos) saved->name += " (default)";
  return saved;
}

std::shared_ptr<const SavedModel> readModelFile(const std::filesystem::path& file) {
  auto saved = std::make_shared<SavedModel>();
  saved->model = loadModel(file);
  checkModel(saved->model, file.string());
  saved->file = file;
  saved->name = file.filename().string();
  return saved;
}

bool isModelFile(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".ewm";
}

}  // namespace ew::ui
