#include "c2f/core/uai.hpp"

#include "c2f/core/memory_budget.hpp"
#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/support/output_file.hpp"
#include "c2f/support/text_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace c2f {

namespace {

class TokenReader {
 public:
  TokenReader(std::istream& in, std::string_view source) : in_(in), source_(source) {}

  std::string word(const std::string& what) {
    std::string token;
    if (!(in_ >> token)) fail("unexpected end of file, expected " + what);
    ++count_;
    return token;
  }

  long integer(const std::string& what, long min, long max) {
    const std::string token = word(what);
    const std::optional<long long> value = parse_integer(token);
    if (!value) fail("expected " + what + ", got '" + printable(token) + "'");
    if (*value < min || *value > max) {
      fail(what + " " + printable(token) + " is out of range [" + std::to_string(min) + ", " +
           std::to_string(max) + "]");
    }
    return static_cast<long>(*value);
  }

  double real(const std::string& what) {
    const std::string token = word(what);
    const std::optional<double> value = parse_real(token);
    if (!value) fail("expected " + what + ", got '" + printable(token) + "'");
    return *value;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw std::invalid_argument(std::string(source_) + ": token " + std::to_string(count_) + ": " +
                                message);
  }

 private:
  std::istream& in_;
  std::string_view source_;
  long count_ = 0;
};

double cost_of(double potential, TokenReader& reader, const std::string& where) {
  if (!(potential > 0.0))
    reader.fail(where + ": potential " + format_real(potential) + " is not > 0 (infinite cost)");
  return -std::log(potential);
}

}  // namespace

namespace {

/// The energy of the UAI text `whole` (named `source`); when `budget` is given, the memory its
/// declarations imply must fit it before the unary costs are allocated.
PairwiseEnergy parse_uai(const std::string& whole, std::string_view source,
                         const MemoryBudget* budget) {
  if (is_gzip(whole)) {
    throw std::invalid_argument(std::string(source) +
                                ": a gzip-compressed file, not UAI text: decompress it first "
                                "(gunzip)");
  }
  const std::string_view text = without_byte_order_mark(whole);
  const auto bytes = static_cast<long long>(text.size());
  std::istringstream in{std::string(text)};
  TokenReader reader(in, source);
  auto require_room = [&](long long count, long long bytes_each, const std::string& what) {
    if (count > bytes / bytes_each) {
      reader.fail(what + " " + std::to_string(count) + " is more than the file's " +
                  std::to_string(bytes) + " bytes can hold");
    }
  };
  const std::string kind = reader.word("the network type");
  if (kind != "MARKOV")
    reader.fail("network type '" + printable(kind) + "' is not supported (expected MARKOV)");
  const long num_variables = reader.integer("the number of variables", 1, 0xffffffffL);
  require_room(num_variables, 2, "the number of variables");
  long num_labels = 0;
  for (long v = 0; v < num_variables; ++v) {
    const long card =
        reader.integer("the cardinality of variable " + std::to_string(v), 1, 1 << 20);
    if (v == 0) num_labels = card;
    if (card != num_labels) {
      reader.fail("variable " + std::to_string(v) + " has cardinality " + std::to_string(card) +
                  ", variable 0 has " + std::to_string(num_labels) + " (all must be equal)");
    }
  }
  const long num_factors = reader.integer("the number of factors", 0, 1L << 40);
  require_room(num_factors, 4, "the number of factors");
  std::vector<std::vector<VariableIndex>> scopes(static_cast<std::size_t>(num_factors));
  for (long f = 0; f < num_factors; ++f) {
    const std::string name = "factor " + std::to_string(f);
    const long arity = reader.integer("the scope size of " + name, 0, 1 << 20);
    if (arity != 1 && arity != 2) {
      reader.fail(name + " has " + std::to_string(arity) +
                  " variables; only unary and pairwise factors are supported");
    }
    for (long k = 0; k < arity; ++k) {
      scopes[f].push_back(static_cast<VariableIndex>(
          reader.integer("a variable of " + name, 0, num_variables - 1)));
    }
    if (arity == 2 && scopes[f][0] == scopes[f][1])
      reader.fail(name + " joins variable " + std::to_string(scopes[f][0]) + " to itself");
  }
  if (budget != nullptr) {
    // The unary costs, a pairwise table in reading and as a term (when there is a pairwise
    // factor), a scope and an edge per factor, and the text (kept twice while it is parsed).
    const double labels = static_cast<double>(num_labels);
    const bool pairwise = std::any_of(scopes.begin(), scopes.end(),
                                      [](const auto& scope) { return scope.size() == 2; });
    const double need = 8.0 * static_cast<double>(num_variables) * labels +
                        (pairwise ? 16.0 * labels * labels : 0.0) +
                        64.0 * static_cast<double>(num_factors) +
                        2.0 * static_cast<double>(whole.size());
    budget->require(
        std::string(source) + " (" + std::to_string(num_variables) + " variables x " +
            std::to_string(num_labels) + " labels, " + std::to_string(num_factors) + " factors)",
        need < 1.8e19 ? std::optional<std::size_t>(static_cast<std::size_t>(need)) : std::nullopt);
  }
  const auto L = static_cast<std::size_t>(num_labels);
  constexpr std::size_t kMaxCosts = std::size_t{1} << 30;  // 8 GiB of unary costs
  if (static_cast<std::size_t>(num_variables) > kMaxCosts / L) {
    reader.fail(std::to_string(num_variables) + " variables x " + std::to_string(num_labels) +
                " labels need more than 8 GiB of unary costs");
  }
  std::vector<double> unaries(static_cast<std::size_t>(num_variables) * L, 0.0);
  std::vector<PairwiseTerm> terms;
  std::map<std::vector<double>, std::uint32_t> term_of_table;
  std::vector<Edge> edges;
  for (long f = 0; f < num_factors; ++f) {
    const std::string name = "factor " + std::to_string(f);
    const std::size_t expected = scopes[f].size() == 1 ? L : L * L;
    const long entries = reader.integer("the table size of " + name, 0, 1L << 40);
    if (static_cast<std::size_t>(entries) != expected) {
      reader.fail(name + " has " + std::to_string(entries) + " table entries, expected " +
                  std::to_string(expected));
    }
    require_room(entries, 2, "the table size of " + name);
    std::vector<double> costs(expected);
    for (std::size_t k = 0; k < expected; ++k)
      costs[k] = cost_of(reader.real("a potential of " + name), reader, name);
    if (scopes[f].size() == 1) {
      double* row = unaries.data() + static_cast<std::size_t>(scopes[f][0]) * L;
      for (std::size_t l = 0; l < L; ++l) row[l] += costs[l];
    } else {
      auto [it, inserted] =
          term_of_table.try_emplace(costs, static_cast<std::uint32_t>(terms.size()));
      if (inserted) terms.push_back(PairwiseTerm::table(static_cast<int>(num_labels), costs));
      edges.push_back(Edge{scopes[f][0], scopes[f][1], 1.0, it->second});
    }
  }
  if (std::string extra; in >> extra)
    reader.fail("unexpected '" + extra + "' after the last table (trailing data)");
  return PairwiseEnergy(static_cast<std::size_t>(num_variables), static_cast<int>(num_labels),
                        std::move(unaries), std::move(terms), std::move(edges));
}

}  // namespace

PairwiseEnergy read_uai(std::istream& stream, std::string_view source) {
  // The whole text first: its size bounds every count the file declares, so a short file
  // cannot make the reader allocate for 2^40 entries it does not hold.
  const std::string whole((std::istreambuf_iterator<char>(stream)),
                          std::istreambuf_iterator<char>());
  return parse_uai(whole, source, nullptr);
}

PairwiseEnergy read_uai_file(const std::string& path, const MemoryBudget& budget) {
  // The text is kept twice while it is parsed: the file may take half the budget.
  const std::string whole = read_input_file(path, "UAI file", budget.ceiling() / 2);
  return parse_uai(whole, path, &budget);
}

PairwiseEnergy read_uai_file(const std::string& path) {
  return read_uai_file(path, default_memory_budget());
}

void write_uai(const PairwiseEnergy& energy, std::ostream& out, const std::function<bool()>& stop) {
  const int L = energy.num_labels();
  // Potentials exp(-(cost - the factor's minimum cost)) lie in (0, 1]: any finite costs whose
  // spread within one factor stays below ~708 are written as normal doubles, and every energy
  // difference survives the round trip (the energy read back is the original minus the sum of
  // the factors' minima, a constant).
  // Tables are written from their costs directly, in two passes (the lowest cost, then the
  // potentials): nothing of size L x L is allocated, whatever the label count.
  std::size_t tables = 0;
  auto write_table = [&](std::size_t count, const auto& cost, const std::string& where) {
    if (stop && ++tables % 1024 == 0 && stop())
      throw WriteStopped("writing the UAI model stopped before its end");
    double lowest = cost(0);
    for (std::size_t k = 1; k < count; ++k) lowest = std::min(lowest, cost(k));
    out << "\n" << count << "\n";
    for (std::size_t k = 0; k < count; ++k) {
      const double value = std::exp(-(cost(k) - lowest));
      if (!(value >= std::numeric_limits<double>::min())) {
        throw std::invalid_argument("write_uai: " + where + ": costs " + format_real(lowest) +
                                    " and " + format_real(cost(k)) +
                                    " are too far apart for a UAI potential (spread > 708)");
      }
      out << c_format("%.17g", value)
          << (k + 1 < count && (k + 1) % static_cast<std::size_t>(L) != 0 ? ' ' : '\n');
    }
  };
  const auto labels = static_cast<std::size_t>(L);
  out << "MARKOV\n" << energy.num_variables() << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v)
    out << L << (v + 1 < energy.num_variables() ? ' ' : '\n');
  out << energy.num_variables() + energy.edges().size() << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v) out << "1 " << v << "\n";
  for (const Edge& e : energy.edges()) out << "2 " << e.u << ' ' << e.v << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v) {
    write_table(
        labels, [&](std::size_t k) { return energy.unary(v, static_cast<Label>(k)); },
        "unary of variable " + std::to_string(v));
  }
  for (std::size_t i = 0; i < energy.edges().size(); ++i) {
    const Edge& e = energy.edges()[i];
    write_table(
        labels * labels,
        [&](std::size_t k) {
          return energy.pairwise_cost(e, static_cast<Label>(k / labels),
                                      static_cast<Label>(k % labels));
        },
        "edge " + std::to_string(i));
  }
}

std::uintmax_t uai_bytes_estimate(const PairwiseEnergy& energy) {
  // Each potential is written with 17 significant digits: at most 23 characters and a
  // separator; the header and factor scopes are small beside the tables.
  constexpr std::uintmax_t kBytesPerPotential = 24;
  const auto labels = static_cast<std::uintmax_t>(energy.num_labels());
  const auto variables = static_cast<std::uintmax_t>(energy.num_variables());
  const auto edges = static_cast<std::uintmax_t>(energy.edges().size());
  return kBytesPerPotential * (variables * labels + edges * labels * labels) +
         32 * (variables + edges) + 64;
}

void write_uai_file(const PairwiseEnergy& energy, const std::string& path,
                    const std::function<bool()>& stop) {
  // A model of a large image with many labels runs to tens of GB: refuse before writing what
  // the disk cannot hold (devices and pipes aside).
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path target(path);
  const bool special = fs::exists(target, error) && !fs::is_regular_file(target, error);
  if (!special) {
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const fs::space_info space = fs::space(folder, error);
    const std::uintmax_t needed = uai_bytes_estimate(energy);
    if (!error && needed > space.available) {
      auto gb = [](std::uintmax_t bytes) {
        return c_format("%.1f GB", static_cast<double>(bytes) / 1e9);
      };
      throw std::runtime_error("writing the UAI model '" + path + "' needs about " + gb(needed) +
                               " (" + std::to_string(energy.num_labels()) + "^2 potentials on " +
                               std::to_string(energy.edges().size()) +
                               " edges), and the disk holding it has " + gb(space.available) +
                               " free");
    }
  }
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  write_uai(energy, out, stop);
  close_checked(out, path);
}

void write_uai_mpe(std::span<const Label> labeling, std::ostream& out) {
  out << "MPE\n" << labeling.size();
  for (const Label label : labeling) out << ' ' << label;
  out << '\n';
}

void write_uai_mpe_file(std::span<const Label> labeling, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  write_uai_mpe(labeling, out);
  close_checked(out, path);
}

Labeling read_uai_mpe(std::istream& stream, std::string_view source, std::size_t num_variables,
                      int num_labels) {
  const std::string text((std::istreambuf_iterator<char>(stream)),
                         std::istreambuf_iterator<char>());
  // The last solution counts: whatever follows the last -BEGIN- line.
  std::string_view solution = text;
  if (const std::size_t begin = solution.rfind("-BEGIN-"); begin != std::string_view::npos)
    solution.remove_prefix(begin + 7);
  std::istringstream in{std::string(solution)};
  TokenReader reader(in, source);
  std::string first = reader.word("MPE or the number of variables");
  if (first == "MPE") first = reader.word("the number of variables");
  const std::optional<long long> count = parse_integer(first);
  if (!count || *count < 0 || static_cast<unsigned long long>(*count) != num_variables) {
    reader.fail("expected the number of variables " + std::to_string(num_variables) + ", got '" +
                first + "'");
  }
  Labeling labeling(num_variables);
  for (std::size_t v = 0; v < num_variables; ++v) {
    labeling[v] = static_cast<Label>(
        reader.integer("the label of variable " + std::to_string(v), 0, num_labels - 1));
  }
  if (std::string extra; in >> extra)
    reader.fail("unexpected '" + extra + "' after the last label (trailing data)");
  return labeling;
}

}  // namespace c2f
