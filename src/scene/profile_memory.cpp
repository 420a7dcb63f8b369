#include "scene/profile_memory.hpp"

#include <unistd.h>

#include <cstdio>

namespace tehl::internal {

namespace {

double PhysicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

std::string Gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / (1 << 30));
  return text;
}

}  // namespace

double ProfileBytes(long long nodes, long long rows, bool thermal, int film_nodes, bool field) {
  double per_node = 2;                                    // p, h
  if (thermal) per_node += 3 + (field ? film_nodes : 0);  // T_mid, T1, T2 (and T(x, z))
  return 8.0 * per_node * static_cast<double>(nodes) * static_cast<double>(rows);
}

void CheckProfileMemory(Document& doc,
                        const FilmCase& film,
                        long long nodes,
                        long long rows,
                        bool journal,
                        const std::string& steps_section,
                        const std::string& steps_key,
                        std::vector<std::string>& notes) {
  const bool thermal = film.effects.thermal;
  const bool field = thermal && doc.Bool("output", "temperature_field");
  const int nz = film.options.film_nodes;
  const double bytes = ProfileBytes(nodes, rows, thermal, nz, field);
  if (bytes < kProfileNoteBytes) return;
  const bool profiles = doc.Bool("output", "profiles");
  char text[640];
  std::snprintf(text, sizeof text,
                "%lld films on %lld nodes keep %s of profiles (p, h%s%s) in memory%s%s; fewer "
                "[numerics] grid_points or steps%s make them smaller",
                rows, nodes, Gigabytes(bytes).c_str(), thermal ? ", T_mid, T1, T2" : "",
                field ? " and T(x, z)" : "", journal ? " and in the checkpoint journal" : "",
                profiles ? ", and write as much to the result file" : "",
                field ? ", or [output] temperature_field = false," : "");
  const double ram = PhysicalMemoryBytes();
  if (!(ram > 0) || bytes < 0.8 * ram) {
    notes.push_back(text);
    return;
  }
  const double field_bytes = field ? bytes - ProfileBytes(nodes, rows, true, nz, false) : 0.0;
  const std::string rule = "the run's profiles would take " + Gigabytes(bytes) +
                           ", more than 80 % of this machine's memory (" + Gigabytes(ram) + ")";
  const std::string allowed = "profiles below " + Gigabytes(0.8 * ram) +
                              " (8 bytes x nodes x steps x arrays, docs/results.md)";
  if (field_bytes > 0.5 * bytes)
    doc.Problem("output", "temperature_field", rule, allowed + ": temperature_field = false");
  else if (film.grid_points > 0)
    doc.Problem("numerics", "grid_points", rule, allowed);
  else
    doc.Problem(steps_section, steps_key, rule, allowed);
}

}  // namespace tehl::internal
