#include "core/eigenwalker/model_membership.h"

#include <algorithm>
#include <cctype>
#include <cmath>


namespace ew {
namespace {

// Within this RMS (mm, over the 225 values) a walker is the model walker it matches.
constexpr double kSameWalkerRmsMm = 1.0;

bool isLetters(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalpha(c); });
}

// "SM2014001" names "2014001" (a manifest's short letter prefix before a file's subject).
bool namesSubject(const std::string& modelSubject, const std::string& subject) {
  if (modelSubject == subject) return true;
  if (subject.empty() || modelSubject.size() <= subject.size()) return false;
  const std::size_t prefix = modelSubject.size() - subject.size();
  return prefix <= 4 && modelSubject.compare(prefix, subject.size(), subject) == 0 &&
         isLetters(modelSubject.substr(0, prefix));
}

}  // namespace

std::string subjectInModel(const EigenwalkerModel& model, const std::string& subject, const Eigen::VectorXd& w) {
  for (const auto& s : model.subjects)
    if (namesSubject(s, subject)) return s;
  if (w.size() != model.mean.size() || model.coefficients.cols() == 0) return "";
  const Eigen::VectorXd k = projectOntoModel(model, w);
  const double limit = kSameWalkerRmsMm * std::sqrt(static_cast<double>(model.mean.size()));
  for (Eigen::Index r = 0; r < model.coefficients.cols(); ++r)
    if ((model.coefficients.col(r) - k).norm() < limit) return model.subjects[static_cast<std::size_t>(r)];
  return "";
}

EigenwalkerModel modelWithoutSubject(const EigenwalkerModel& model, const std::string& subject) {
  ModelOptions every;
  every.components = model.walkerCount();  // clamped to R' − 1 by the engine
  return buildModelWithoutSubject(storedWalkerVectors(model), model.walkerIds, model.subjects, model.omegasRadS,
                                  subject, every);
}

}  // namespace ew
