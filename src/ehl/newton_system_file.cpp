#include "ehl/newton_system_file.hpp"

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace tehl::internal {
namespace {

constexpr char kMagic[8] = {'T', 'E', 'H', 'L', 'N', 'S', '0', '1'};

template <class T>
void Put(std::ofstream& f, const T* data, std::size_t count) {
  f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(sizeof(T) * count));
}

template <class T>
void Get(std::ifstream& f, const std::string& path, T* data, std::size_t count) {
  f.read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(sizeof(T) * count));
  if (!f) throw std::runtime_error(path + ": truncated Newton system file");
}

}  // namespace

void WriteNewtonSystem(const std::string& path,
                       const NewtonSystem& sys,
                       const Eigen::VectorXd& rhs) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  const std::int32_t n = sys.n;
  const double head[5] = {sys.dx, sys.p_ref, sys.h_ref, sys.load,
                          sys.elastic ? sys.elastic->e_prime_pa() : 0.0};
  Put(f, kMagic, 8);
  Put(f, &n, 1);
  Put(f, head, 5);
  Put(f, sys.row_scale->data(), n);
  Put(f, sys.a->data(), 4 * static_cast<std::size_t>(n));
  Put(f, sys.b->data(), 4 * static_cast<std::size_t>(n));
  Put(f, sys.cavitated.data(), n);
  Put(f, rhs.data(), static_cast<std::size_t>(rhs.size()));
  if (!f) throw std::runtime_error(path + ": write failed");
}

std::unique_ptr<StoredNewtonSystem> ReadNewtonSystem(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot open");
  char magic[8];
  Get(f, path, magic, 8);
  if (std::memcmp(magic, kMagic, 8) != 0)
    throw std::runtime_error(path + ": not a Newton system file (no TEHLNS01 header)");
  std::int32_t n = 0;
  Get(f, path, &n, 1);
  if (n < 5 || n > (1 << 26)) throw std::runtime_error(path + ": grid size out of range");
  double head[5];
  Get(f, path, head, 5);
  auto s = std::make_unique<StoredNewtonSystem>();
  s->row_scale.resize(n);
  s->a.resize(n, 4);
  s->b.resize(n, 4);
  s->rhs.resize(n - 1);
  NewtonSystem& sys = s->system;
  sys.cavitated.resize(n);
  Get(f, path, s->row_scale.data(), n);
  Get(f, path, s->a.data(), 4 * static_cast<std::size_t>(n));
  Get(f, path, s->b.data(), 4 * static_cast<std::size_t>(n));
  Get(f, path, sys.cavitated.data(), n);
  Get(f, path, s->rhs.data(), static_cast<std::size_t>(n - 1));
  if (head[4] > 0) s->kernel = std::make_unique<ElasticDeflection>(n, head[0], head[4]);
  sys.n = n;
  sys.dx = head[0];
  sys.p_ref = head[1];
  sys.h_ref = head[2];
  sys.load = head[3];
  sys.row_scale = &s->row_scale;
  sys.a = &s->a;
  sys.b = &s->b;
  sys.elastic = s->kernel.get();
  return s;
}

void MaybeWriteNewtonSystem(const NewtonSystem& sys, const Eigen::VectorXd& rhs) {
  const char* prefix = std::getenv("TEHL_WRITE_NEWTON_SYSTEMS");
  if (!prefix || !*prefix) return;
  static std::atomic<int> count{0};
  static std::atomic<bool> reported{false};
  const std::string path =
      std::string(prefix) + "_" + std::to_string(sys.n) + "_" + std::to_string(count++) + ".bin";
  try {
    WriteNewtonSystem(path, sys, rhs);
  } catch (const std::exception& e) {
    if (!reported.exchange(true)) std::fprintf(stderr, "TEHL_WRITE_NEWTON_SYSTEMS: %s\n", e.what());
  }
}

}  // namespace tehl::internal
