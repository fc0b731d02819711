#pragma once
// The run layer's one kind of refusal: a configuration field that is not usable, or a memory
// budget the run's floor does not fit, named so that each front end can say it in its own
// vocabulary (a tool's --flag, a Python keyword).

#include <stdexcept>
#include <string>

namespace c2f {

class RunConfigError : public std::invalid_argument {
 public:
  /// what() is "<field>: <problem>".
  RunConfigError(std::string field, std::string problem)
      : std::invalid_argument(field + ": " + problem),
        field_(std::move(field)),
        problem_(std::move(problem)) {}

  /// The configuration's field: "solver.original", "limits", "memory", ...
  [[nodiscard]] const std::string& field() const noexcept { return field_; }
  /// What is wrong with it, without the field's name.
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

  /// Throws a RunConfigError for a non-empty `message` of the form "<field>: <problem>" (as the
  /// run layer's validators write them); does nothing for an empty one.
  static void throw_if(const std::string& message);

 private:
  std::string field_;
  std::string problem_;
};

}  // namespace c2f
