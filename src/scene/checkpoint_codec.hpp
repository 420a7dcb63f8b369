// The binary encoding of mesh-cycle checkpoints (mesh_cycle_checkpoint.hpp): the format
// magics, the FNV-1a checksum, a sequential writer and reader of the few types a checkpoint
// holds, and the encoding of contact conditions and cycle rows. Private to src/scene.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "tehl/ehl/line_contact_solver.hpp"
#include "tehl/scene/mesh_cycle_scene.hpp"

namespace tehl::internal::checkpoint_codec {

// The last character of each magic is the format's version.
inline constexpr char kMagic[8] = {'T', 'E', 'H', 'L', 'C', 'K', 'P', 'A'};
inline constexpr char kRowsMagic[8] = {'T', 'E', 'H', 'L', 'R', 'O', 'W', '5'};
inline constexpr std::int64_t kRowsHeaderBytes = sizeof kRowsMagic + sizeof(std::uint64_t);
inline constexpr std::uint64_t kChecksumBytes = sizeof(std::uint64_t);

// FNV-1a, 64 bit, continued from `h`: stable across runs and builds (std::hash is not required
// to be), and any change of a single byte changes it (each step is a bijection of the state).
inline constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;
inline std::uint64_t Fnv1a(const char* p, size_t n, std::uint64_t h = kFnvOffset) {
  for (size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(p[i]);
    h *= 1099511628211ull;
  }
  return h;
}

// The profile arrays of a result, in journal order.
inline std::array<std::vector<std::vector<double>>*, 6> Profiles(MeshCycleResult& r) {
  return {&r.p_pa, &r.h_m, &r.t_mid_k, &r.t1_k, &r.t2_k, &r.t_field_k};
}
inline std::array<const std::vector<std::vector<double>>*, 6> Profiles(const MeshCycleResult& r) {
  return {&r.p_pa, &r.h_m, &r.t_mid_k, &r.t1_k, &r.t2_k, &r.t_field_k};
}

// Sequential binary writer / reader of the few types a checkpoint holds.
class Out {
 public:
  void Raw(const void* p, size_t n) {
    if (n == 0) return;  // an empty field: its data pointer may be null
    const size_t old = buf_.size();
    buf_.resize(old + n);
    std::memcpy(buf_.data() + old, p, n);
  }
  void F(double v) { Raw(&v, sizeof v); }
  void I(std::int64_t v) { Raw(&v, sizeof v); }
  void S(const std::string& s) {
    I(static_cast<std::int64_t>(s.size()));
    Raw(s.data(), s.size());
  }
  void V(const double* p, std::int64_t n) {
    I(n);
    Raw(p, static_cast<size_t>(n) * sizeof(double));
  }
  void V(const Eigen::VectorXd& v) { V(v.data(), v.size()); }
  void V(const std::vector<double>& v) { V(v.data(), static_cast<std::int64_t>(v.size())); }
  void M(const Eigen::MatrixXd& m) {
    I(m.rows());
    I(m.cols());
    Raw(m.data(), static_cast<size_t>(m.size()) * sizeof(double));
  }
  void VV(const std::vector<std::vector<double>>& v) {
    I(static_cast<std::int64_t>(v.size()));
    for (const auto& row : v) V(row);
  }
  const std::vector<char>& bytes() const { return buf_; }

 private:
  std::vector<char> buf_;
};

class In {
 public:
  explicit In(std::vector<char> b) : buf_(std::move(b)) {}
  void Raw(void* p, size_t n) {
    if (pos_ + n > buf_.size()) throw std::runtime_error("truncated checkpoint");
    if (n == 0) return;  // an empty field: its data pointer may be null
    std::memcpy(p, buf_.data() + pos_, n);
    pos_ += n;
  }
  double F() {
    double v;
    Raw(&v, sizeof v);
    return v;
  }
  std::int64_t I() {
    std::int64_t v;
    Raw(&v, sizeof v);
    return v;
  }
  std::int64_t Count() {
    const std::int64_t n = I();
    if (n < 0 || static_cast<size_t>(n) > buf_.size()) throw std::runtime_error("bad length");
    return n;
  }
  std::string S() {
    std::string s(static_cast<size_t>(Count()), '\0');
    Raw(s.data(), s.size());
    return s;
  }
  std::vector<double> V() {
    std::vector<double> v(static_cast<size_t>(Count()));
    Raw(v.data(), v.size() * sizeof(double));
    return v;
  }
  Eigen::VectorXd E() {
    const std::vector<double> v = V();
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
  }
  Eigen::MatrixXd M() {
    const std::int64_t r = Count(), c = Count();
    Eigen::MatrixXd m(r, c);
    Raw(m.data(), static_cast<size_t>(m.size()) * sizeof(double));
    return m;
  }
  std::vector<std::vector<double>> VV() {
    std::vector<std::vector<double>> v(static_cast<size_t>(Count()));
    for (auto& row : v) row = V();
    return v;
  }
  bool done() const { return pos_ == buf_.size(); }

 private:
  std::vector<char> buf_;
  size_t pos_ = 0;
};

void PutConditions(Out& o, const ContactConditions& c);
ContactConditions GetConditions(In& in);
void PutStep(Out& o, const MeshCycleStep& k);  // a /cycle row with its solver Summary
MeshCycleStep GetStep(In& in);

}  // namespace tehl::internal::checkpoint_codec
