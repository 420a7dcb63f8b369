#include "scene/mesh_cycle_checkpoint.hpp"

#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <vector>

namespace tehl::internal {
namespace {

constexpr char kMagic[8] = {'T', 'E', 'H', 'L', 'C', 'K', 'P', '6'};
constexpr char kRowsMagic[8] = {'T', 'E', 'H', 'L', 'R', 'O', 'W', '3'};
constexpr std::int64_t kRowsHeaderBytes = sizeof kRowsMagic + sizeof(std::uint64_t);

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
  for (double v : {k.s_m, k.time_s, k.reduced_radius_m, k.u1_m_s, k.u2_m_s, k.um_m_s, k.srr,
                   k.load_n_per_m, k.static_load_n_per_m, k.h_min_m, k.h_c_m, k.p_max_pa, k.t_max_k, k.t_mid_max_k,
                   k.t1_max_k, k.t2_max_k, k.friction_coefficient, k.c_rt, k.c_ut, k.c_wt})
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
  for (double* v : {&k.s_m, &k.time_s, &k.reduced_radius_m, &k.u1_m_s, &k.u2_m_s, &k.um_m_s,
                    &k.srr, &k.load_n_per_m, &k.static_load_n_per_m, &k.h_min_m, &k.h_c_m, &k.p_max_pa, &k.t_max_k,
                    &k.t_mid_max_k, &k.t1_max_k, &k.t2_max_k, &k.friction_coefficient, &k.c_rt,
                    &k.c_ut, &k.c_wt})
    *v = in.F();
  k.pairs_in_contact = static_cast<int>(in.I());
  k.zone = in.S();
  LineContactSolver::Summary& s = k.summary;
  s.termination = static_cast<LineContactSolver::Termination>(in.I());
  s.message = in.S();
  for (int* v : {&s.iterations, &s.total_iterations, &s.continuation_stages,
                 &s.krylov_iterations, &s.substeps, &s.coupling_iterations})
    *v = static_cast<int>(in.I());
  for (double* v : {&s.residual, &s.load_error, &s.wall_time_s, &s.temperature_change_k,
                    &s.energy_balance_error, &s.time_error})
    *v = in.F();
  s.linear_solver = in.S();
  k.restart_reason = in.S();
  return k;
}

}  // namespace

std::uint64_t CaseFingerprint(const std::string& text) {
  // FNV-1a, 64 bit: stable across runs and builds (std::hash is not required to be).
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string CheckpointRowsPath(const std::string& checkpoint_path) {
  return checkpoint_path + ".rows";
}

CheckpointWriter::CheckpointWriter(std::string checkpoint_path)
    : path_(std::move(checkpoint_path)) {}

void CheckpointWriter::ContinueFrom(const MeshCycleCheckpoint& c) {
  journal_id_ = c.journal_id;
  journal_bytes_ = c.journal_bytes;
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

  // 2. The checkpoint proper, which commits the journal up to `committed`.
  Out o;
  o.Raw(kMagic, sizeof kMagic);
  o.I(static_cast<std::int64_t>(fingerprint));
  o.I(next_step);
  o.F(elapsed_s);
  o.I(static_cast<std::int64_t>(journal_id_));
  o.I(committed);
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

  const std::string tmp = path_ + ".part";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f.write(o.bytes().data(), static_cast<std::streamsize>(o.bytes().size()));
    f.flush();
    if (!f) throw std::runtime_error("cannot write the checkpoint " + tmp);
  }
  std::filesystem::rename(tmp, path_);
  journal_bytes_ = committed;
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
  std::ifstream f(path, std::ios::binary);
  if (!f || bytes < 0) return std::nullopt;
  std::vector<char> b(static_cast<size_t>(bytes));
  f.read(b.data(), bytes);
  if (f.gcount() != bytes) return std::nullopt;
  return b;
}

}  // namespace

std::optional<MeshCycleCheckpoint> ReadCheckpoint(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return std::nullopt;
  std::vector<char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  try {
    In in(std::move(bytes));
    char magic[8];
    in.Raw(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof magic) != 0) return std::nullopt;
    MeshCycleCheckpoint c;
    c.fingerprint = static_cast<std::uint64_t>(in.I());
    c.next_step = static_cast<int>(in.I());
    c.elapsed_s = in.F();
    c.journal_id = static_cast<std::uint64_t>(in.I());
    c.journal_bytes = in.I();
    std::array<std::int64_t, 7> counts{};
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
    if (!in.done() || c.journal_bytes < kRowsHeaderBytes) return std::nullopt;

    // The committed part of the journal: its header, then one chunk per checkpoint.
    std::optional<std::vector<char>> rows = ReadPrefix(CheckpointRowsPath(path), c.journal_bytes);
    if (!rows) return std::nullopt;
    In j(std::move(*rows));
    j.Raw(magic, sizeof magic);
    if (std::memcmp(magic, kRowsMagic, sizeof magic) != 0) return std::nullopt;
    if (static_cast<std::uint64_t>(j.I()) != c.journal_id) return std::nullopt;
    MeshCycleResult& r = c.result;
    const auto profiles = Profiles(r);
    while (!j.done()) {
      for (std::int64_t k = j.Count(); k > 0; --k) r.steps.push_back(GetStep(j));
      for (auto* a : profiles)
        for (std::int64_t k = j.Count(); k > 0; --k) a->push_back(j.V());
    }
    if (static_cast<std::int64_t>(r.steps.size()) != counts[0]) return std::nullopt;
    for (size_t a = 0; a < profiles.size(); ++a)
      if (static_cast<std::int64_t>(profiles[a]->size()) != counts[a + 1]) return std::nullopt;
    return c;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace tehl::internal
