#include "core/keypoints/openpose_writer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {
namespace {

using nlohmann::json;

struct Point {
  Joint joint;
  double du, dv;  // offset in shares of the person's image height
};

// BODY_25 in its order, each point from a joint and an offset.
const Point kBody25[25] = {
    {Joint::Head, 0, 0.02},       {Joint::Sternum, 0, 0},       {Joint::RShoulder, 0, 0},   {Joint::RElbow, 0, 0},
    {Joint::RWrist, 0, 0},        {Joint::LShoulder, 0, 0},     {Joint::LElbow, 0, 0},      {Joint::LWrist, 0, 0},
    {Joint::Pelvis, 0, 0},        {Joint::RHip, 0, 0},          {Joint::RKnee, 0, 0},       {Joint::RAnkle, 0, 0},
    {Joint::LHip, 0, 0},          {Joint::LKnee, 0, 0},         {Joint::LAnkle, 0, 0},      {Joint::Head, -0.012, -0.01},
    {Joint::Head, 0.012, -0.01},  {Joint::Head, -0.04, 0},      {Joint::Head, 0.04, 0},     {Joint::LAnkle, 0.05, 0.04},
    {Joint::LAnkle, 0.06, 0.035}, {Joint::LAnkle, -0.02, 0.035}, {Joint::RAnkle, 0.05, 0.04}, {Joint::RAnkle, 0.06, 0.035},
    {Joint::RAnkle, -0.02, 0.035}};

// COCO-17 in its order (AlphaPose, MMPose): the same points as BODY_25's, without the neck,
// the mid-hip and the feet.
const Point kCoco17[17] = {
    {Joint::Head, 0, 0.02},       {Joint::Head, 0.012, -0.01}, {Joint::Head, -0.012, -0.01}, {Joint::Head, 0.04, 0},
    {Joint::Head, -0.04, 0},      {Joint::LShoulder, 0, 0},    {Joint::RShoulder, 0, 0},      {Joint::LElbow, 0, 0},
    {Joint::RElbow, 0, 0},        {Joint::LWrist, 0, 0},       {Joint::RWrist, 0, 0},         {Joint::LHip, 0, 0},
    {Joint::RHip, 0, 0},          {Joint::LKnee, 0, 0},        {Joint::RKnee, 0, 0},          {Joint::LAnkle, 0, 0},
    {Joint::RAnkle, 0, 0}};

double heightPx(const Eigen::MatrixXd& px, Eigen::Index f) {
  const double ankles = 0.5 * (px(f, 2 * index(Joint::LAnkle) + 1) + px(f, 2 * index(Joint::RAnkle) + 1));
  return std::abs(ankles - px(f, 2 * index(Joint::Head) + 1));
}

template <std::size_t N>
json keypointTriples(const OpenPosePerson& p, Eigen::Index f, const Point (&points)[N]) {
  const double h = heightPx(p.jointsPx, f);
  json flat = json::array();
  for (const Point& pt : points) {
    const double u = p.jointsPx(f, 2 * index(pt.joint)), v = p.jointsPx(f, 2 * index(pt.joint) + 1);
    const double c = p.confidence.size() ? p.confidence(f, index(pt.joint)) : 0.9;
    const bool seen = std::isfinite(u) && std::isfinite(v) && std::isfinite(h);
    flat.insert(flat.end(), {seen ? u + pt.du * h : 0.0, seen ? v + pt.dv * h : 0.0, seen ? c : 0.0});
  }
  return flat;
}

bool inFrame(const OpenPosePerson& p, Eigen::Index f) {
  return f < p.jointsPx.rows() && p.jointsPx.row(f).array().isFinite().any();
}

void writeJson(const std::filesystem::path& file, const json& doc) {
  std::ofstream out(file);
  out << doc.dump();
  if (!out) throw Error(ErrorKind::Io, file.string(), "", "cannot write");
}

}  // namespace

void writeOpenPoseBody25(const std::filesystem::path& folder, const std::vector<OpenPosePerson>& people) {
  std::filesystem::create_directories(folder);
  const Eigen::Index frames = people.empty() ? 0 : people.front().jointsPx.rows();
  for (Eigen::Index f = 0; f < frames; ++f) {
    json list = json::array();
    for (const auto& p : people)
      if (inFrame(p, f)) list.push_back({{"person_id", {-1}}, {"pose_keypoints_2d", keypointTriples(p, f, kBody25)}});
    char name[64];
    std::snprintf(name, sizeof name, "clip_%012ld_keypoints.json", static_cast<long>(f));
    writeJson(folder / name, json{{"version", 1.3}, {"people", list}});
  }
}

void writeAlphaPoseCoco17(const std::filesystem::path& file, const std::vector<OpenPosePerson>& people) {
  const Eigen::Index frames = people.empty() ? 0 : people.front().jointsPx.rows();
  json list = json::array();
  for (Eigen::Index f = 0; f < frames; ++f)
    for (const auto& p : people)
      if (inFrame(p, f))
        list.push_back({{"image_id", std::to_string(f) + ".jpg"}, {"category_id", 1},
                        {"keypoints", keypointTriples(p, f, kCoco17)}, {"score", 2.5}});
  writeJson(file, list);
}

}  // namespace ew
