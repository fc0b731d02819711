#include "c2f/driver/observer.hpp"

namespace c2f {

Labeling StepEvent::ground_labeling() const {
  Labeling ground;
  const std::span<const Label> labels = ground_labeling(ground);
  if (labels.data() != ground.data()) ground.assign(labels.begin(), labels.end());
  return ground;
}

std::span<const Label> StepEvent::ground_labeling(Labeling& scratch) const {
  if (group_of.empty()) return level_labeling;
  scratch.resize(group_of.size());
  for (std::size_t v = 0; v < group_of.size(); ++v) scratch[v] = level_labeling[group_of[v]];
  return scratch;
}

Observer observe_all(std::vector<Observer> observers) {
  return [observers = std::move(observers)](const StepEvent& event) {
    ObserverDecision decision = ObserverDecision::continue_run;
    for (const Observer& observer : observers) {
      if (observer && observer(event) == ObserverDecision::stop) decision = ObserverDecision::stop;
    }
    return decision;
  };
}

}  // namespace c2f
