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

double heightPx(const Eigen::MatrixXd& px, Eigen::Index f) {
  const double ankles = 0.5 * (px(f, 2 * index(Joint::LAnkle) + 1) + px(f, 2 * index(Joint::RAnkle) + 1));
  return std::abs(ankles - px(f, 2 * index(Joint::Head) + 1));
}

json personJson(const OpenPosePerson& p, Eigen::Index f) {
  const double h = heightPx(p.jointsPx, f);
  json flat = json::array();
  for (const Point& pt : kBody25) {
    const double u = p.jointsPx(f, 2 * index(pt.joint)), v = p.jointsPx(f, 2 * index(pt.joint) + 1);
    const double c = p.confidence.size() ? p.confidence(f, index(pt.joint)) : 0.9;
    const bool seen = std::isfinite(u) && std::isfinite(v) && std::isfinite(h);
    flat.insert(flat.end(), {seen ? u + pt.du * h : 0.0, seen ? v + pt.dv * h : 0.0, seen ? c : 0.0});
  }
  return {{"person_id", {-1}}, {"pose_keypoints_2d", flat}};
}

}  // namespace

void writeOpenPoseBody25(const std::filesystem::path& folder, const std::vector<OpenPosePerson>& people) {
  std::filesystem::create_directories(folder);
  const Eigen::Index frames = people.empty() ? 0 : people.front().jointsPx.rows();
  for (Eigen::Index f = 0; f < frames; ++f) {
    json list = json::array();
    for (const auto& p : people) {
      if (f < p.jointsPx.rows() && p.jointsPx.row(f).array().isFinite().any()) list.push_back(personJson(p, f));
    }
    char name[64];
    std::snprintf(name, sizeof name, "clip_%012ld_keypoints.json", static_cast<long>(f));
    const auto file = folder / name;
    std::ofstream out(file);
    out << json{{"version", 1.3}, {"people", list}}.dump();
    if (!out) throw Error(ErrorKind::Io, file.string(), "", "cannot write");
  }
}

}  // namespace ew
