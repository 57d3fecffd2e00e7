#include "core/experiments/leave_one_out.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/common/errors.h"

namespace ew {

std::vector<ExperimentWalker> experimentWalkers(const std::vector<Walker>& walkers,
                                                const Dataset& dataset) {
  std::vector<ExperimentWalker> out;
  out.reserve(walkers.size());
  for (const Walker& w : walkers) {
    ExperimentWalker e{w.id, w.subject, w.source, w.fit, {}, 0.0};
    if (!w.files.empty()) {
      for (const DatasetTrial& t : dataset.trials) {
        if (t.info.file != w.files.front()) continue;
        e.framesMm = t.trial.joints.positionsMm;
        e.rateHz = t.trial.joints.rateHz;
        break;
      }
    }
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<std::string> walkerSubjects(const std::vector<ExperimentWalker>& walkers) {
  std::vector<std::string> out;
  for (const auto& w : walkers) {
    if (std::find(out.begin(), out.end(), w.subject) == out.end()) out.push_back(w.subject);
  }
  return out;
}

Eigen::MatrixXd experimentWalkerMatrix(const std::vector<ExperimentWalker>& walkers) {
  Eigen::MatrixXd w(kFourierDims3, static_cast<Eigen::Index>(walkers.size()));
  for (size_t r = 0; r < walkers.size(); ++r) {
    // Checked here: a column assignment of the wrong size is not caught in a release build.
    if (walkers[r].fit.w.size() != kFourierDims3)
      throw Error(ErrorKind::BadArgument, "", "",
                  "leave-one-subject-out: walker '" + walkers[r].id + "' has " +
                      std::to_string(walkers[r].fit.w.size()) +
                      " Fourier values, a 3D fit has 225");
    w.col(static_cast<Eigen::Index>(r)) = walkers[r].fit.w;
  }
  return w;
}

namespace {

struct ModelInputs {
  Eigen::MatrixXd w;
  std::vector<std::string> ids, subjects;
  Eigen::VectorXd omegas;
};

ModelInputs modelInputs(const std::vector<ExperimentWalker>& walkers) {
  ModelInputs in{experimentWalkerMatrix(walkers), {}, {},
                 Eigen::VectorXd(static_cast<Eigen::Index>(walkers.size()))};
  for (size_t r = 0; r < walkers.size(); ++r) {
    in.ids.push_back(walkers[r].id);
    in.subjects.push_back(walkers[r].subject);
    in.omegas(static_cast<Eigen::Index>(r)) = walkers[r].fit.omegaRadS;
  }
  return in;
}

}  // namespace

EigenwalkerModel buildFullModel(const std::vector<ExperimentWalker>& walkers,
                                const ModelOptions& options) {
  const ModelInputs in = modelInputs(walkers);
  return buildModel(in.w, in.ids, in.subjects, in.omegas, options);
}

std::vector<Fold> buildFolds(const std::vector<ExperimentWalker>& walkers,
                             const ModelOptions& options, int threads) {
  const std::vector<std::string> subjects = walkerSubjects(walkers);
  if (subjects.size() < 3) {
    throwBadData("", "", "leave-one-subject-out needs walkers of at least 3 subjects, got " +
                             std::to_string(subjects.size()));
  }
  const ModelInputs in = modelInputs(walkers);
  std::vector<Fold> folds(subjects.size());
  parallelFor(static_cast<int>(subjects.size()), threads, [&](int f) {
    Fold& fold = folds[static_cast<size_t>(f)];
    fold.subject = subjects[static_cast<size_t>(f)];
    for (size_t r = 0; r < walkers.size(); ++r) {
      if (walkers[r].subject == fold.subject) fold.testWalkers.push_back(static_cast<int>(r));
    }
    fold.model = buildModelWithoutSubject(in.w, in.ids, in.subjects, in.omegas, fold.subject, options);
    fold.gram = precomputeModelGram(fold.model);
  });
  return folds;
}

void parallelFor(int count, int threads, const std::function<void(int)>& body) {
  const int workers = std::clamp(threads, 1, std::max(count, 1));
  std::atomic<int> next{0};
  std::exception_ptr firstError;
  std::mutex errorMutex;
  auto work = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard lock(errorMutex);
        if (!firstError) firstError = std::current_exception();
        next = count;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (firstError) std::rethrow_exception(firstError);
}

std::uint64_t cellSeed(std::uint64_t seed, size_t walker, size_t angle, size_t level) {
  std::uint64_t z = seed ^ (walker * 0x9E3779B97F4A7C15ull) ^ (angle * 0xBF58476D1CE4E5B9ull) ^
                    (level * 0x94D049BB133111EBull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;  // splitmix64's finaliser
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace ew
