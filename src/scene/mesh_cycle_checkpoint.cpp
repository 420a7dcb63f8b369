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

#include "scene/checkpoint_codec.hpp"

namespace tehl::internal {

using namespace checkpoint_codec;  // NOLINT(google-build-using-namespace): private codec

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
  // The solids' heat history (infinite travels: a steady level).
  for (double v : {t.travel1_m, t.travel2_m, t.speed1_m_s, t.speed2_m_s}) o.F(v);
  o.I(static_cast<std::int64_t>(t.earlier.size()));
  for (const SolidFluxLevel& l : t.earlier) {
    o.V(l.q1_w_m2);
    o.V(l.q2_w_m2);
    for (double v : {l.travel1_m, l.travel2_m, l.speed1_m_s, l.speed2_m_s}) o.F(v);
  }
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

}  // namespace tehl::internal
