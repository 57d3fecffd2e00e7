#include "ui/app/derived.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/engines/request.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/projection.h"
#include "core/engines/engine.h"
#include "core/snippet/snippet_prior.h"
#include "ui/app/held_model.h"

namespace ew::ui {

Eigen::VectorXd frameAtPhase(const Eigen::VectorXd& w, double phase01) {
  Eigen::VectorXd t(1);
  t(0) = 2.0 * std::numbers::pi * phase01;
  return synthesizeFrames(w, 1.0, 0.0, t).row(0).transpose();
}

Eigen::MatrixXd trailOverCycle(const Eigen::VectorXd& w, int samples) {
  const Eigen::VectorXd t =
      Eigen::VectorXd::LinSpaced(samples, 0.0, 2.0 * std::numbers::pi * (samples - 1) / samples);
  return synthesizeFrames(w, 1.0, 0.0, t);
}

std::pair<double, std::string> walkerSpeedMps(const Document& doc, int walker) {
  if (const WalkerFacts* f = doc.factsAt(walker); f && f->speedMps && *f->speedMps > 0.0)
    return {*f->speedMps, "measured"};
  double sum = 0.0;
  int n = 0;
  if (doc.population)
    for (const auto& f : doc.population->facts)
      if (f.speedMps && *f.speedMps > 0.0 && std::isfinite(*f.speedMps)) sum += *f.speedMps, ++n;
  if (n > 0) return {sum / n, "population mean"};
  return {1.3, "typical adult"};
}

namespace {

std::vector<FourierWalkerTrial> populationPriorWalkers(const Document& doc, const std::string& withoutSubject) {
  std::vector<FourierWalkerTrial> walkers;
  for (int i = 0; i < doc.population->walkerCount(); ++i) {
    const Walker& w = doc.population->walkers[static_cast<std::size_t>(i)];
    if (w.subject == withoutSubject) continue;
    walkers.push_back({w.subject, w.id, w.fit.w, w.fit.omegaRadS, walkerSpeedMps(doc, i).first});
  }
  return walkers;
}

}  // namespace

SnippetPriorCache::Entry SnippetPriorCache::get(const Document& doc, int index) {
  const EigenwalkerModel* held = heldModelOtherThanThePopulations(doc);
  if (generation_ != doc.generation || population_ != doc.population.get() || model_ != held) {
    entries_.clear();
    generation_ = doc.generation;
    population_ = doc.population.get();
    model_ = held;
  }
  const Walker* walker = doc.walkerAt(index);
  if (!walker) throw std::runtime_error("snippet engine: no walker " + std::to_string(index));
  // The subject left out, as the eigenwalker's leave-one-out names it (held_model.h).
  const std::string without = held ? subjectInModel(*held, *walker) : walker->subject;
  if (auto it = entries_.find(without); it != entries_.end()) return it->second;
  if (!held && !doc.population) throw std::runtime_error("snippet engine: no population to learn a prior from");
  const std::vector<FourierWalkerTrial> walkers = held ? modelFourierWalkers(*held, without) : populationPriorWalkers(doc, without);
  Entry e;
  e.walkers = static_cast<int>(walkers.size());
  e.prior = std::make_shared<const PreparedSnippetPrior>(
      prepareSnippetPrior(trainSnippetPrior(snippetTrialsFromFourier(walkers), {})));
  ++trainings_;
  return entries_[without] = e;
}

namespace {

// An engine's 30 Hz frames as r.estimate: one cycle (fourierSummary at the walker's ω), and
// as k that cycle's nearest model coefficients (read only in the viewer).
void summariseAsOneCycle(const EngineResult& e, double omegaRadS, ReconBase& r) {
  r.estimate = Reconstruction{};
  r.estimate.alphaDeg = e.alphaDeg;
  r.estimate.w = fourierSummary(e.framesMm, 30.0, omegaRadS);
  r.estimate.k = projectOntoModel(r.model, r.estimate.w);
  r.estimate.wDataPreserving = r.estimate.w;
}

// The snippet engine on the walker, walked overground and seen at the true α: its frames
// summarised as one cycle into r.estimate (w, and k as that w's nearest model coefficients).
void reconstructWithSnippets(const Document& doc, const ReconKey& key, const Walker& walker,
                             SnippetPriorCache& priors, ReconBase& r) {
  const SnippetPriorCache::Entry prior = priors.get(doc, key.walker);
  r.priorWalkers = prior.walkers;
  std::tie(r.speedMps, r.speedSource) = walkerSpeedMps(doc, key.walker);
  const double omega = walker.fit.omegaRadS;
  ViewInput in;
  in.uvMm = projectFramesToView(overgroundFrames(r.wTrue, omega, r.speedMps, kSnippetCycles, 30.0),
                                key.settings.alphaDeg);
  in.rateHz = 30.0;
  if (!key.settings.unknownAngle) in.alphaDeg = key.settings.alphaDeg;
  in.name = walker.id;
  const EngineResult e = reconstruct(SnippetEngine{prior.prior, {}}, {in}).engine;
  summariseAsOneCycle(e, omega, r);
  r.snippets = e.snippet;
}

// The skeleton engine on the walker walking in place (an orthographic view shows no motion
// along the line of sight, and the engine puts the pelvis at depth 0) for kSnippetCycles at
// 30 Hz, with the walker's own bone lengths (the paper measures its performer); summarised
// as one cycle like the snippet engine's.
void reconstructWithSkeleton(const ReconKey& key, const Walker& walker, ReconBase& r) {
  const double omega = walker.fit.omegaRadS;
  const Eigen::MatrixXd frames = overgroundFrames(r.wTrue, omega, 0.0, kSnippetCycles, 30.0);
  ViewInput in;
  in.uvMm = projectFramesToView(frames, key.settings.alphaDeg);
  in.rateHz = 30.0;
  if (!key.settings.unknownAngle) in.alphaDeg = key.settings.alphaDeg;
  in.name = walker.id;
  SkeletonEngine engine;
  engine.bones = boneLengthsFromFrames(frames, walker.id);
  const EngineResult e = reconstruct(engine, {in}).engine;
  summariseAsOneCycle(e, omega, r);
  r.skeleton = e.skeleton;
}

std::unique_ptr<ReconBase> computeRecon(const Document& doc, const ReconKey& key, SnippetPriorCache& priors) {
  const Walker& walker = *doc.walkerAt(key.walker);
  const WalkerModel chosen = modelForWalker(doc, key.walker);
  const EigenwalkerModel& loo = chosen.model;
  auto r = std::make_unique<ReconBase>();
  r->heldOutSubject = chosen.heldOutSubject;
  r->inModel = chosen.member;
  r->inspected = doc.isInspected(key.walker);
  r->modelName = heldModelName(doc);
  r->modelEstimated = doc.factsAt(key.walker)->modelEstimated;
  r->modelWalkers = loo.walkerCount();
  r->autoComponents = key.settings.components <= 0;
  r->components = r->autoComponents ? autoComponentCount(loo)
                                    : std::min(key.settings.components, loo.componentCount());
  r->explained = explainedShare(loo, r->components);
  r->model = truncateModel(loo, r->components);
  // Joints the trial never measured are not part of its 2D view: their rows are dropped
  // from the likelihood (the model estimates them), as `reconstruct` does for the CLI.
  std::vector<int> notMeasured;
  for (int j = 0; j < kJointCount; ++j)
    if (r->modelEstimated[static_cast<std::size_t>(j)]) notMeasured.push_back(j);
  r->gram = precomputeModelGram(r->model, notMeasured);
  r->sd = r->model.eigenvalues.cwiseMax(0.0).cwiseSqrt();
  r->wTrue = walker.fit.w;
  r->alphaTrueDeg = key.settings.alphaDeg;
  r->observed = projectToView(r->wTrue, key.settings.alphaDeg);
  r->observedTrail = trailOverCycle(r->observed, kTrailSamples);
  r->strideHz = walker.fit.omegaRadS / (2.0 * std::numbers::pi);
  r->engine = key.settings.engine;
  if (r->engine == EngineKind::Snippet || r->engine == EngineKind::Skeleton) {
    if (r->engine == EngineKind::Snippet)
      reconstructWithSnippets(doc, key, walker, priors, *r);
    else
      reconstructWithSkeleton(key, walker, *r);
    r->alphaUsedDeg = r->estimate.alphaDeg;
    return r;
  }
  EstimatorOptions est;
  est.estimator = key.settings.estimator;
  est.sigma2Mm2 = key.settings.sigma2Mm2;
  EigenwalkerDiagnostics d = reconstructFourierView(
      r->gram, r->observed, key.settings.unknownAngle ? std::nullopt : std::optional<double>(key.settings.alphaDeg), est);
  r->search = std::move(d.search);
  r->estimate = std::move(d.reconstruction);
  r->alphaUsedDeg = r->estimate.alphaDeg;
  return r;
}

std::unique_ptr<ReconDisplay> computeDisplay(const ReconBase& base,
                                             const std::vector<double>& editedSd) {
  auto d = std::make_unique<ReconDisplay>();
  const auto n = base.sd.size();
  Eigen::VectorXd k = base.estimate.k;
  // The snippet and skeleton engines' k only describes their result: edits do not apply to it.
  if (base.engine == EngineKind::Eigenwalker && static_cast<Eigen::Index>(editedSd.size()) == n) {
    for (Eigen::Index i = 0; i < n; ++i) k(i) = editedSd[static_cast<std::size_t>(i)] * base.sd(i);
    d->edited = true;
  }
  d->kSd = k.cwiseQuotient(base.sd.cwiseMax(1e-12));
  d->w = d->edited ? synthesizeWalker(base.model, k) : base.estimate.w;
  d->reprojected = projectToView(d->w, base.alphaUsedDeg);
  d->errors = depthErrors(base.wTrue, d->w, base.alphaTrueDeg);
  d->depthRmsMm = d->errors.absPerJoint.cwiseMax(0.0).cwiseSqrt();
  const Eigen::VectorXd perJoint = mpjpePerJoint(base.wTrue, d->w);
  double measured = 0.0, estimated = 0.0, absMeasured = 0.0;
  int nMeasured = 0, nEstimated = 0;
  for (int j = 0; j < kJointCount; ++j) {
    const bool model = base.modelEstimated[static_cast<std::size_t>(j)];
    (model ? estimated : measured) += perJoint(j);
    if (!model) absMeasured += d->errors.absPerJoint(j);
    ++(model ? nEstimated : nMeasured);
  }
  d->jointsScored = nMeasured;
  d->mpjpeMeasuredMm = nMeasured > 0 ? measured / nMeasured : 0.0;
  d->mpjpeMm = d->mpjpeMeasuredMm;
  d->absScoredMm2 = nMeasured > 0 ? absMeasured / nMeasured : 0.0;
  d->relScored = d->errors.sigmaM2Mm2 > 0.0 ? d->absScoredMm2 / d->errors.sigmaM2Mm2 : 0.0;
  if (nEstimated > 0) d->mpjpeModelEstimatedMm = estimated / nEstimated;
  d->residualRmsMm =
      std::sqrt((base.observed - d->reprojected).squaredNorm() / static_cast<double>(base.observed.size()));
  d->angleErrorDeg = viewAngleErrorDeg(base.alphaUsedDeg, base.alphaTrueDeg);
  return d;
}

// Every engine on the walker with the same settings; one engine's failure is its entry's error.
std::unique_ptr<CompareResult> computeCompare(const Document& doc, const ReconKey& key, SnippetPriorCache& priors) {
  auto out = std::make_unique<CompareResult>();
  for (EngineKind kind : kEngineKinds) {
    CompareEntry entry;
    entry.engine = kind;
    ReconKey k = key;
    k.settings.engine = kind;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      std::shared_ptr<const ReconBase> base = computeRecon(doc, k, priors);
      entry.display = computeDisplay(*base, {});
      entry.base = std::move(base);
    } catch (const std::exception& e) {
      entry.error = e.what();
    }
    entry.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out->engines.push_back(std::move(entry));
  }
  return out;
}

std::unique_ptr<ExploreResult> computeExplore(const Document& doc, const ExploreKey& key) {
  const EigenwalkerModel& all = *doc.heldModel();
  auto e = std::make_unique<ExploreResult>();
  e->autoComponents = key.components <= 0;
  e->components = e->autoComponents ? autoComponentCount(all)
                                    : std::min(key.components, all.componentCount());
  e->explained = explainedShare(all, e->components);
  const EigenwalkerModel m = truncateModel(all, e->components);
  e->sd = m.eigenvalues.cwiseMax(0.0).cwiseSqrt();
  e->shares = m.eigenvalues / std::max(all.spectrum.sum(), 1e-12);
  Eigen::VectorXd k = Eigen::VectorXd::Zero(e->components);
  for (Eigen::Index i = 0; i < k.size() && i < static_cast<Eigen::Index>(key.sd.size()); ++i)
    k(i) = key.sd[static_cast<std::size_t>(i)] * e->sd(i);
  e->k = k;
  e->w = synthesizeWalker(m, k);
  e->projected = projectToView(e->w, key.alphaDeg);
  e->projectedTrail = trailOverCycle(e->projected, kTrailSamples);
  const double meanOmega = all.omegasRadS.size() > 0 ? all.omegasRadS.mean() : 2.0 * std::numbers::pi * 0.9;
  // A semantic axis may move ω; a stride frequency outside the Fourier scan's range is no walk.
  e->strideHz = std::clamp(meanOmega + key.omegaOffsetRadS, 2.0 * std::numbers::pi * 0.3, 2.0 * std::numbers::pi * 2.5) /
                (2.0 * std::numbers::pi);
  e->modelWalkers = all.walkerCount();
  e->modelName = heldModelName(doc);
  return e;
}

}  // namespace

const CompareEntry* CompareResult::of(EngineKind kind) const {
  for (const auto& e : engines)
    if (e.engine == kind) return &e;
  return nullptr;
}

void Derived::update(const Document& doc) {
  if (!doc.ready()) {
    compareKey_.reset();
    compare_.reset();
    reconKey_.reset();
    displayKey_.reset();
    exploreKey_.reset();
    recon_.reset();
    display_.reset();
    explore_.reset();
    semanticKey_.reset();
    semantic_.reset();
    fromViewKey_.reset();
    fromView_.clear();
    viewAxesKey_.reset();
    viewAxes_ = {};
    return;
  }
  try {
    const ReconKey rk{doc.generation, doc.walker, doc.recon};
    if (!doc.walkerAt(doc.walker)) throw std::runtime_error("no walker selected");
    if (!reconKey_ || !(*reconKey_ == rk)) {
      recon_.reset();
      display_.reset();
      displayKey_.reset();
      reconKey_ = rk;
      ++reconComputations_;
      error_.clear();
      recon_ = computeRecon(doc, rk, snippetPriors_);
    }
    if (recon_) {
      const DisplayKey dk{rk, doc.editedSd};
      if (!displayKey_ || !(*displayKey_ == dk)) {
        displayKey_ = dk;
        display_ = computeDisplay(*recon_, doc.editedSd);
      }
    }
    if (doc.compareEngines && doc.mode == Mode::Reconstruct) {
      ReconKey ck = rk;
      ck.settings.engine = EngineKind::Eigenwalker;
      if (!compareKey_ || !(*compareKey_ == ck)) {
        compareKey_ = ck;
        compare_ = computeCompare(doc, ck, snippetPriors_);
      }
    } else {
      compareKey_.reset();
      compare_.reset();
    }
    const ExploreKey ek{doc.generation, doc.recon.components, doc.exploreSd, doc.exploreOmegaOffsetRadS,
                        doc.recon.alphaDeg};
    if (!exploreKey_ || !(*exploreKey_ == ek)) {
      exploreKey_ = ek;
      explore_ = computeExplore(doc, ek);
    }
    updateSemantic(doc);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

const AxesWalkers& Derived::populationAxes(const Document& doc) {
  if (!populationAxesWalkers_ || attributesGeneration_ != doc.generation) {
    populationAxesWalkers_ = std::make_unique<const AxesWalkers>(populationAxesWalkers(*doc.population));
    attributesGeneration_ = doc.generation;
  }
  return *populationAxesWalkers_;
}

const AxesWalkers& Derived::heldModelAxes(const Document& doc, const EigenwalkerModel& held) {
  const std::pair<std::uint64_t, const EigenwalkerModel*> key{doc.generation, &held};
  if (!modelAxesWalkers_ || modelAxesWalkersKey_ != key) {
    modelAxesWalkers_ = std::make_unique<const AxesWalkers>(modelAxesWalkers(held, heldModelPhrase(doc)));
    modelAxesWalkersKey_ = key;
  }
  return *modelAxesWalkers_;
}

// The explorer's axes in explore mode; the attributes from the 2D view in reconstruct mode.
void Derived::updateSemantic(const Document& doc) {
  const EigenwalkerModel* held = heldModelOtherThanThePopulations(doc);
  const int referenceWalkers = held ? held->walkerCount() : doc.population ? doc.population->walkerCount() : 0;
  if (referenceWalkers < kMinPopulation) {
    semanticKey_.reset();
    semantic_.reset();
    fromViewKey_.reset();
    fromView_.clear();
    return;
  }
  if (doc.mode == Mode::Explore && explore_) {
    const SemanticAxesKey key{doc.generation, explore_->components, held};
    if (!semanticKey_ || !(*semanticKey_ == key)) {
      semanticKey_ = key;
      const AxesWalkers& from = held ? heldModelAxes(doc, *held) : populationAxes(doc);
      semantic_ = std::make_unique<SemanticAxes>(fitAxes(from, truncateModel(*doc.heldModel(), key.components)));
    }
  }
  if (doc.mode != Mode::Reconstruct || !recon_ || !reconKey_ || !doc.selectedWalker()) {
    fromViewKey_.reset();
    fromView_.clear();
  } else if (!fromViewKey_ || !(*fromViewKey_ == *reconKey_)) {
    fromViewKey_ = reconKey_;
    const Walker& self = *doc.selectedWalker();
    const auto axesKey = std::make_tuple(doc.generation, doc.walker, recon_->components, doc.modelSource, doc.modelFile);
    if (!viewAxesKey_ || *viewAxesKey_ != axesKey) {
      viewAxesKey_ = axesKey;
      // The reference walkers are the held model's; a population member is one of them (its
      // manifest's values known) when the model is the population's own.
      const AxesWalkers& reference = held ? heldModelAxes(doc, *held) : populationAxes(doc);
      const int referenceIndex = held || recon_->inspected ? -1 : doc.walker;
      const std::string without = held ? (recon_->inModel ? recon_->heldOutSubject : "") : self.subject;
      viewAxes_ = fitViewAxes(reference, without, ownAttributeValues(reference, referenceIndex, self), recon_->model);
    }
    fromView_ = ui::attributesFromView(viewAxes_, self.fit.omegaRadS, *recon_);
  }
}

}  // namespace ew::ui
