#include "c2f/core/uai.hpp"

#include "c2f/core/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <map>
#include <optional>
#include <ostream>
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
    if (!value) fail("expected " + what + ", got '" + token + "'");
    if (*value < min || *value > max) {
      fail(what + " " + token + " is out of range [" + std::to_string(min) + ", " +
           std::to_string(max) + "]");
    }
    return static_cast<long>(*value);
  }

  double real(const std::string& what) {
    const std::string token = word(what);
    const std::optional<double> value = parse_real(token);
    if (!value) fail("expected " + what + ", got '" + token + "'");
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
    reader.fail(where + ": potential " + std::to_string(potential) + " is not > 0 (infinite cost)");
  return -std::log(potential);
}

}  // namespace

PairwiseEnergy read_uai(std::istream& in, std::string_view source) {
  TokenReader reader(in, source);
  const std::string kind = reader.word("the network type");
  if (kind != "MARKOV")
    reader.fail("network type '" + kind + "' is not supported (expected MARKOV)");
  const long num_variables = reader.integer("the number of variables", 1, 0xffffffffL);
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
  const auto L = static_cast<std::size_t>(num_labels);
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
  return PairwiseEnergy(static_cast<std::size_t>(num_variables), static_cast<int>(num_labels),
                        std::move(unaries), std::move(terms), std::move(edges));
}

PairwiseEnergy read_uai_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open UAI file '" + path + "'");
  return read_uai(in, path);
}

void write_uai(const PairwiseEnergy& energy, std::ostream& out) {
  const int L = energy.num_labels();
  auto potential = [](double cost, const std::string& where) {
    const double value = std::exp(-cost);
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw std::invalid_argument(
          "write_uai: " + where + ": cost " + std::to_string(cost) +
          " cannot be written as a UAI potential exp(-cost) in double precision");
    }
    return value;
  };
  char number[40];
  out << "MARKOV\n" << energy.num_variables() << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v)
    out << L << (v + 1 < energy.num_variables() ? ' ' : '\n');
  out << energy.num_variables() + energy.edges().size() << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v) out << "1 " << v << "\n";
  for (const Edge& e : energy.edges()) out << "2 " << e.u << ' ' << e.v << "\n";
  for (std::size_t v = 0; v < energy.num_variables(); ++v) {
    out << "\n" << L << "\n";
    for (Label l = 0; l < L; ++l) {
      std::snprintf(number, sizeof number, "%.17g",
                    potential(energy.unary(v, l), "unary of variable " + std::to_string(v)));
      out << number << (l + 1 < L ? ' ' : '\n');
    }
  }
  for (std::size_t i = 0; i < energy.edges().size(); ++i) {
    const Edge& e = energy.edges()[i];
    out << "\n" << L * L << "\n";
    for (Label a = 0; a < L; ++a) {
      for (Label b = 0; b < L; ++b) {
        std::snprintf(number, sizeof number, "%.17g",
                      potential(energy.pairwise_cost(e, a, b), "edge " + std::to_string(i)));
        out << number << (b + 1 < L ? ' ' : '\n');
      }
    }
  }
}

void write_uai_file(const PairwiseEnergy& energy, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  write_uai(energy, out);
  out.flush();
  if (!out) throw std::runtime_error("writing '" + path + "' failed");
}

}  // namespace c2f
