#include "scene/mesh_cycle_checkpoint.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <vector>

namespace tehl::internal {
namespace {

// The last character of each magic is the format's version.
constexpr char kMagic[8] = {'T', 'E', 'H', 'L', 'C', 'K', 'P', '7'};
constexpr char kRowsMagic[8] = {'T', 'E', 'H', 'L', 'R', 'O', 'W', '4'};
constexpr std::int64_t kRowsHeaderBytes = sizeof kRowsMagic + sizeof(std::uint64_t);
constexpr std::uint64_t kChecksumBytes = sizeof(std::uint64_t);

// FNV-1a, 64 bit, continued from `h`: stable across runs and builds (std::hash is not required
// to be), and any change of a single byte changes it (each step is a bijection of the state).
constexpr std::uint64_t kFnvOffset = 1469598103934665603ull;
std::uint64_t Fnv1a(const char* p, size_t n, std::uint64_t h = kFnvOffset) {
  for (size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(p[i]);
    h *= 1099511628211ull;
  }
  return h;
}

// The profile arrays of a result, in journal order.
std::array<std::vector<std::vector<double>>*, 6> Profiles(MeshCycleResult& r) {
  return {&r.p_pa, &r.h_m, &r.t_mid_k, &r.t1_k, &r.t2_k, &r.t_field_k};
}
std::array<const std::vector<std::vector<double>>*, 6> Profiles(const MeshCycleResult& r) {
  return {&r.p_pa, &r.h_m, &r.t_mid_k, &r.t1_k, &r.t2_k, &r.t_field_k};
}

// Sequential binary writer / reader of the few types a checkpoint holds.
class Out {
 public:
  void Raw(const void* p, size_t n) {
    const char* c = static_cast<const char*>(p);
    buf_.insert(buf_.end(), c, c + n);
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

void PutConditions(Out& o, const ContactConditions& c) {
  for (double v : {c.reduced_radius_m, c.u1_m_s, c.u2_m_s, c.load_n_per_m, c.temperature_k}) o.F(v);
}
ContactConditions GetConditions(In& in) {
  ContactConditions c;
  c.reduced_radius_m = in.F();
  c.u1_m_s = in.F();
  c.u2_m_s = in.F();
  c.load_n_per_m = in.F();
  c.temperature_k = in.F();
  return c;
}

void PutStep(Out& o, const MeshCycleStep& k) {
  for (double v : {k.s_m,
                   k.time_s,
                   k.reduced_radius_m,
                   k.u1_m_s,
                   k.u2_m_s,
                   k.um_m_s,
                   k.srr,
                   k.load_n_per_m,
                   k.static_load_n_per_m,
                   k.h_min_m,
                   k.h_c_m,
                   k.p_max_pa,
                   k.t_max_k,
                   k.t_mid_max_k,
                   k.t1_max_k,
                   k.t2_max_k,
                   k.friction_coefficient,
                   k.c_rt,
                   k.c_ut,
                   k.c_wt})
    o.F(v);
  o.I(k.pairs_in_contact);
  o.S(k.zone);
  const LineContactSolver::Summary& s = k.summary;
  o.I(static_cast<int>(s.termination));
  o.S(s.message);
  for (int v : {s.iterations, s.total_iterations, s.continuation_stages, s.krylov_iterations,
                s.substeps, s.coupling_iterations})
    o.I(v);
  for (double v : {s.residual, s.load_error, s.wall_time_s, s.temperature_change_k,
                   s.energy_balance_error, s.time_error})
    o.F(v);
  o.S(s.linear_solver);
  o.S(k.restart_reason);
}

MeshCycleStep GetStep(In& in) {
  MeshCycleStep k;
  for (double* v : {&k.s_m,
                    &k.time_s,
                    &k.reduced_radius_m,
                    &k.u1_m_s,
                    &k.u2_m_s,
                    &k.um_m_s,
                    &k.srr,
                    &k.load_n_per_m,
                    &k.static_load_n_per_m,
                    &k.h_min_m,
                    &k.h_c_m,
                    &k.p_max_pa,
                    &k.t_max_k,
                    &k.t_mid_max_k,
                    &k.t1_max_k,
                    &k.t2_max_k,
                    &k.friction_coefficient,
                    &k.c_rt,
                    &k.c_ut,
                    &k.c_wt})
    *v = in.F();
  k.pairs_in_contact = static_cast<int>(in.I());
  k.zone = in.S();
  LineContactSolver::Summary& s = k.summary;
  s.termination = static_cast<LineContactSolver::Termination>(in.I());
  s.message = in.S();
  for (int* v : {&s.iterations, &s.total_iterations, &s.continuation_stages, &s.krylov_iterations,
                 &s.substeps, &s.coupling_iterations})
    *v = static_cast<int>(in.I());
  for (double* v : {&s.residual, &s.load_error, &s.wall_time_s, &s.temperature_change_k,
                    &s.energy_balance_error, &s.time_error})
    *v = in.F();
  s.linear_solver = in.S();
  k.restart_reason = in.S();
  return k;
}

}  // namespace

std::uint64_t CaseFingerprint(const std::string& text) { return Fnv1a(text.data(), text.size()); }

std::string CheckpointRowsPath(const std::string& checkpoint_path) {
  return checkpoint_path + ".rows";
}

CheckpointWriter::CheckpointWriter(std::string checkpoint_path)
    : path_(std::move(checkpoint_path)) {}

void CheckpointWriter::ContinueFrom(const MeshCycleCheckpoint& c) {
  journal_id_ = c.journal_id;
  journal_bytes_ = c.journal_bytes;
  journal_checksum_ = c.journal_checksum;
  written_[0] = static_cast<std::int64_t>(c.result.steps.size());
  const auto profiles = Profiles(c.result);
  for (size_t a = 0; a < profiles.size(); ++a)
    written_[a + 1] = static_cast<std::int64_t>(profiles[a]->size());
}

void CheckpointWriter::Write(std::uint64_t fingerprint,
                             int next_step,
                             double elapsed_s,
                             const MeshCycleResult& r,
                             const FilmState& s,
                             const LineContactSolver::TransientHistory& history) {
  // 1. The journal: the rows since the last checkpoint, appended past the committed length.
  const std::string rows_path = CheckpointRowsPath(path_);
  Out chunk;
  if (journal_bytes_ == 0) {
    // A new journal's identity: the clock in nanoseconds, the process and the path (no
    // entropy source needed, which std::random_device may lack).
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    journal_id_ = static_cast<std::uint64_t>(
                      std::chrono::duration_cast<std::chrono::nanoseconds>(now).count()) ^
                  (static_cast<std::uint64_t>(getpid()) << 40) ^
                  static_cast<std::uint64_t>(std::hash<std::string>{}(path_));
    chunk.Raw(kRowsMagic, sizeof kRowsMagic);
    chunk.I(static_cast<std::int64_t>(journal_id_));
  }
  std::array<std::int64_t, 7> now{};
  now[0] = static_cast<std::int64_t>(r.steps.size());
  chunk.I(now[0] - written_[0]);
  for (std::int64_t k = written_[0]; k < now[0]; ++k) PutStep(chunk, r.steps[k]);
  const auto profiles = Profiles(r);
  for (size_t a = 0; a < profiles.size(); ++a) {
    now[a + 1] = static_cast<std::int64_t>(profiles[a]->size());
    chunk.I(now[a + 1] - written_[a + 1]);
    for (std::int64_t k = written_[a + 1]; k < now[a + 1]; ++k) chunk.V((*profiles[a])[k]);
  }
  {
    namespace fs = std::filesystem;
    if (journal_bytes_ > 0) {
      // The committed rows must still be there; an uncommitted tail is cut off.
      std::error_code ec;
      const std::uintmax_t size = fs::file_size(rows_path, ec);
      if (ec || static_cast<std::int64_t>(size) < journal_bytes_)
        throw std::runtime_error("the checkpoint journal " + rows_path +
                                 " lost rows it had committed");
      if (static_cast<std::int64_t>(size) > journal_bytes_)
        fs::resize_file(rows_path, static_cast<std::uintmax_t>(journal_bytes_));
    }
    std::ofstream f(rows_path,
                    std::ios::binary | (journal_bytes_ == 0 ? std::ios::trunc : std::ios::app));
    f.write(chunk.bytes().data(), static_cast<std::streamsize>(chunk.bytes().size()));
    f.flush();
    if (!f) throw std::runtime_error("cannot write the checkpoint journal " + rows_path);
  }
  const std::int64_t committed = journal_bytes_ + static_cast<std::int64_t>(chunk.bytes().size());
  const std::uint64_t checksum = Fnv1a(chunk.bytes().data(), chunk.bytes().size(),
                                       journal_bytes_ == 0 ? kFnvOffset : journal_checksum_);

  // 2. The checkpoint proper, which commits the journal up to `committed`.
  Out o;
  o.Raw(kMagic, sizeof kMagic);
  o.I(static_cast<std::int64_t>(fingerprint));
  o.I(next_step);
  o.F(elapsed_s);
  o.I(static_cast<std::int64_t>(journal_id_));
  o.I(committed);
  o.I(static_cast<std::int64_t>(checksum));
  for (std::int64_t n : now) o.I(n);
  o.V(s.p_pa);
  o.V(s.h_m);
  for (double v : {s.h0_m, s.time_s, s.travel1_m, s.travel2_m}) o.F(v);
  const FilmTemperature& t = s.temperature;
  o.M(t.t_k);
  for (const auto* v : {&t.t1_k, &t.t2_k, &t.q1_w_m2, &t.q2_w_m2}) o.V(*v);
  o.I(history.levels);
  o.V(history.q1);
  o.V(history.q2);
  o.V(history.q3);
  o.F(history.dt_prev_s);
  o.F(history.dt_prev2_s);
  o.F(history.next_substep_s);
  PutConditions(o, history.c_prev);
  o.M(history.t_prev_k);
  const std::uint64_t own = Fnv1a(o.bytes().data(), o.bytes().size());
  o.I(static_cast<std::int64_t>(own));  // the checksum of everything before it

  const std::string tmp = path_ + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f.write(o.bytes().data(), static_cast<std::streamsize>(o.bytes().size()));
    f.flush();
    if (!f) throw std::runtime_error("cannot write the checkpoint " + tmp);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write the checkpoint " + path_ + ": " + ec.message());
  }
  journal_bytes_ = committed;
  journal_checksum_ = checksum;
  written_ = now;
}

void CheckpointWriter::Remove() const {
  namespace fs = std::filesystem;
  std::error_code ignored;
  for (const std::string& p : {path_, CheckpointRowsPath(path_)})
    if (fs::is_regular_file(p, ignored)) fs::remove(p, ignored);  // only files it could write
}

namespace {

std::optional<std::vector<char>> ReadPrefix(const std::string& path, std::int64_t bytes) {
  // The size first: a damaged count must not become a huge allocation.
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || bytes < 0 || static_cast<std::uintmax_t>(bytes) > size) return std::nullopt;
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  std::vector<char> b(static_cast<size_t>(bytes));
  f.read(b.data(), bytes);
  if (f.gcount() != bytes) return std::nullopt;
  return b;
}

// Why a checkpoint was not used.
struct Unusable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void RequireFinite(double v, const char* what) {
  if (!std::isfinite(v)) throw Unusable(std::string("it holds a non-finite ") + what);
}
void RequireFinite(const Eigen::Ref<const Eigen::MatrixXd>& m, const char* what) {
  if (!m.allFinite()) throw Unusable(std::string("it holds a non-finite ") + what);
}

// The film and the solver history a run continues from: finite, as every converged level is
// (a checkpoint is written only after a step that converged).
void RequireFinite(const MeshCycleCheckpoint& c) {
  RequireFinite(c.elapsed_s, "wall time");
  const FilmState& s = c.state;
  RequireFinite(s.p_pa, "pressure");
  RequireFinite(s.h_m, "film thickness");
  for (double v : {s.h0_m, s.time_s, s.travel1_m, s.travel2_m}) RequireFinite(v, "film state");
  const FilmTemperature& t = s.temperature;
  RequireFinite(t.t_k, "film temperature");
  for (const auto* v : {&t.t1_k, &t.t2_k, &t.q1_w_m2, &t.q2_w_m2})
    RequireFinite(*v, "surface temperature or heat flux");
  const LineContactSolver::TransientHistory& h = c.history;
  for (const auto* v : {&h.q1, &h.q2, &h.q3}) RequireFinite(*v, "transient history");
  for (double v : {h.dt_prev_s, h.dt_prev2_s, h.next_substep_s, h.c_prev.reduced_radius_m,
                   h.c_prev.u1_m_s, h.c_prev.u2_m_s, h.c_prev.load_n_per_m, h.c_prev.temperature_k})
    RequireFinite(v, "transient history");
  RequireFinite(h.t_prev_k, "transient history");
}

// Reads the checkpoint at `path` and its journal; throws Unusable saying why they cannot be
// used. Returns nullopt when there is no checkpoint.
std::optional<MeshCycleCheckpoint> Read(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return std::nullopt;
  if (ec) throw Unusable("it cannot be examined: " + ec.message());
  if (fs::is_directory(status)) throw Unusable("it is a folder, not a file");
  if (!fs::is_regular_file(status)) throw Unusable("it is not a regular file");
  std::vector<char> bytes;
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Unusable("it cannot be read");
    bytes.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    if (f.bad()) throw Unusable("it cannot be read");
  }
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, 7) != 0)
    throw Unusable("it is not a tehl checkpoint");
  if (bytes[7] != kMagic[7])
    throw Unusable(std::string("it was written by another version of tehl (format ") +
                   std::string(bytes.data(), sizeof kMagic) + "; this version reads " +
                   std::string(kMagic, sizeof kMagic) + ")");
  std::uint64_t stored = 0;
  if (bytes.size() < sizeof kMagic + kChecksumBytes)
    throw Unusable("the file is damaged (it is cut short)");
  std::memcpy(&stored, bytes.data() + bytes.size() - kChecksumBytes, kChecksumBytes);
  bytes.resize(bytes.size() - kChecksumBytes);
  if (Fnv1a(bytes.data(), bytes.size()) != stored)
    throw Unusable("the file is damaged (its checksum does not match its contents)");

  MeshCycleCheckpoint c;
  std::array<std::int64_t, 7> counts{};
  try {
    In in(std::move(bytes));
    char magic[8];
    in.Raw(magic, sizeof magic);
    c.fingerprint = static_cast<std::uint64_t>(in.I());
    c.next_step = static_cast<int>(in.I());
    c.elapsed_s = in.F();
    c.journal_id = static_cast<std::uint64_t>(in.I());
    c.journal_bytes = in.I();
    c.journal_checksum = static_cast<std::uint64_t>(in.I());
    for (auto& n : counts) n = in.I();
    FilmState& s = c.state;
    s.p_pa = in.E();
    s.h_m = in.E();
    for (double* v : {&s.h0_m, &s.time_s, &s.travel1_m, &s.travel2_m}) *v = in.F();
    FilmTemperature& t = s.temperature;
    t.t_k = in.M();
    for (auto* v : {&t.t1_k, &t.t2_k, &t.q1_w_m2, &t.q2_w_m2}) *v = in.E();
    c.history.levels = static_cast<int>(in.I());
    c.history.q1 = in.E();
    c.history.q2 = in.E();
    c.history.q3 = in.E();
    c.history.dt_prev_s = in.F();
    c.history.dt_prev2_s = in.F();
    c.history.next_substep_s = in.F();
    c.history.c_prev = GetConditions(in);
    c.history.t_prev_k = in.M();
    if (!in.done() || c.journal_bytes < kRowsHeaderBytes) throw std::runtime_error("layout");
  } catch (const std::exception&) {
    throw Unusable("the file is damaged (its contents do not have the layout of a checkpoint)");
  }
  RequireFinite(c);

  // The committed part of the journal: its header, then one chunk per checkpoint.
  const std::string rows_path = CheckpointRowsPath(path);
  if (!fs::is_regular_file(rows_path, ec))
    throw Unusable("its rows file " + rows_path + " is missing or not a file");
  std::optional<std::vector<char>> rows = ReadPrefix(rows_path, c.journal_bytes);
  if (!rows)
    throw Unusable("its rows file " + rows_path + " is shorter than the checkpoint records");
  // The checksum first: a damaged header is damage, not another version.
  if (Fnv1a(rows->data(), rows->size()) != c.journal_checksum)
    throw Unusable("its rows file " + rows_path +
                   " is damaged or belongs to another run (its checksum does not match the "
                   "one the checkpoint records)");
  if (std::memcmp(rows->data(), kRowsMagic, sizeof kRowsMagic) != 0)
    throw Unusable("its rows file " + rows_path + " is not of this version of tehl");
  try {
    In j(std::move(*rows));
    char magic[8];
    j.Raw(magic, sizeof magic);
    if (static_cast<std::uint64_t>(j.I()) != c.journal_id) throw std::runtime_error("identity");
    MeshCycleResult& r = c.result;
    const auto profiles = Profiles(r);
    while (!j.done()) {
      for (std::int64_t k = j.Count(); k > 0; --k) r.steps.push_back(GetStep(j));
      for (auto* a : profiles)
        for (std::int64_t k = j.Count(); k > 0; --k) a->push_back(j.V());
    }
    if (static_cast<std::int64_t>(r.steps.size()) != counts[0])
      throw std::runtime_error("row count");
    for (size_t a = 0; a < profiles.size(); ++a)
      if (static_cast<std::int64_t>(profiles[a]->size()) != counts[a + 1])
        throw std::runtime_error("profile count");
  } catch (const std::exception&) {
    throw Unusable("its rows file " + rows_path + " does not hold the rows the checkpoint records");
  }
  return c;
}

}  // namespace

std::optional<MeshCycleCheckpoint> ReadCheckpoint(const std::string& path, std::string* problem) {
  if (problem) problem->clear();
  try {
    return Read(path);
  } catch (const std::exception& e) {
    if (problem) *problem = e.what();
    return std::nullopt;
  }
}

}  // namespace tehl::internal
