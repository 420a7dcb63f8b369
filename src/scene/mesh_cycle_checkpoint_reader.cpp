// Reading a mesh-cycle checkpoint and its journal, refusing any that cannot be trusted
// (mesh_cycle_checkpoint.hpp).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "scene/checkpoint_codec.hpp"
#include "scene/mesh_cycle_checkpoint.hpp"

namespace tehl::internal {

using namespace checkpoint_codec;  // NOLINT(google-build-using-namespace): private codec

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
  // Travels >= 0 (infinite: a steady level), speeds finite and >= 0.
  auto require_level = [](double travel1, double travel2, double speed1, double speed2) {
    if (!(travel1 >= 0 && travel2 >= 0))
      throw Unusable("it holds a negative or undefined travel of a heat-flux level");
    RequireFinite(speed1, "surface speed of a heat-flux level");
    RequireFinite(speed2, "surface speed of a heat-flux level");
    if (speed1 < 0 || speed2 < 0) throw Unusable("it holds a negative surface speed");
  };
  require_level(t.travel1_m, t.travel2_m, t.speed1_m_s, t.speed2_m_s);
  for (const SolidFluxLevel& l : t.earlier) {
    RequireFinite(l.q1_w_m2, "earlier heat flux");
    RequireFinite(l.q2_w_m2, "earlier heat flux");
    require_level(l.travel1_m, l.travel2_m, l.speed1_m_s, l.speed2_m_s);
  }
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
    for (double* v : {&t.travel1_m, &t.travel2_m, &t.speed1_m_s, &t.speed2_m_s}) *v = in.F();
    const std::int64_t levels = in.I();
    if (levels < 0 || levels > kMaxSolidFluxLevels)
      throw Unusable("it holds " + std::to_string(levels) + " earlier heat-flux levels");
    t.earlier.resize(static_cast<size_t>(levels));
    for (SolidFluxLevel& l : t.earlier) {
      l.q1_w_m2 = in.E();
      l.q2_w_m2 = in.E();
      for (double* v : {&l.travel1_m, &l.travel2_m, &l.speed1_m_s, &l.speed2_m_s}) *v = in.F();
    }
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

ResumePoint ResumeFromCheckpoint(const std::string& path,
                                 std::uint64_t fingerprint,
                                 size_t films,
                                 int grid_nodes,
                                 bool quiet,
                                 CheckpointWriter* writer,
                                 MeshCycleResult* r,
                                 FilmState* state,
                                 LineContactSolver* solver) {
  ResumePoint at;
  std::string unusable;  // why a checkpoint that is there cannot be used
  std::optional<MeshCycleCheckpoint> ck = ReadCheckpoint(path, &unusable);
  if (ck && ck->fingerprint == fingerprint && ck->next_step >= 1 &&
      static_cast<size_t>(ck->next_step) < films &&
      ck->result.steps.size() == static_cast<size_t>(ck->next_step) &&
      ck->state.p_pa.size() == grid_nodes) {
    writer->ContinueFrom(*ck);
    r->steps = std::move(ck->result.steps);
    for (auto [to, from] : {std::pair{&r->p_pa, &ck->result.p_pa},
                            {&r->h_m, &ck->result.h_m},
                            {&r->t_mid_k, &ck->result.t_mid_k},
                            {&r->t1_k, &ck->result.t1_k},
                            {&r->t2_k, &ck->result.t2_k},
                            {&r->t_field_k, &ck->result.t_field_k}})
      *to = std::move(*from);
    *state = std::move(ck->state);
    solver->RestoreTransient(ck->history);
    at.first_step = static_cast<size_t>(ck->next_step);
    at.elapsed_s = ck->elapsed_s;
    at.resumed_from_step = ck->next_step;
  } else if (!unusable.empty()) {  // printed even when quiet, as a checkpoint not written is
    std::fprintf(stderr, "warning: the checkpoint %s is not used: %s; starting at A\n",
                 path.c_str(), unusable.c_str());
  } else if (!quiet) {
    std::fprintf(stderr, "no usable checkpoint %s for this case: starting at A\n", path.c_str());
  }
  return at;
}

}  // namespace tehl::internal
