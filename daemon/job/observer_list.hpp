#pragma once
// ObserverList: one StatusObserver that hands every change to several (MQTT and the operator's
// page), in the order added. Each observer keeps its own contract: return at once, never block.
#include <vector>

#include "daemon/job/status_observer.hpp"

namespace lastcut::daemon {

class ObserverList : public StatusObserver {
 public:
  void add(StatusObserver* observer) {
    if (observer) observers_.push_back(observer);
  }
  bool empty() const { return observers_.empty(); }
  void job_changed(const JobEvent& event) override {
    for (StatusObserver* observer : observers_) observer->job_changed(event);
  }
  void cutter_changed(const CutterStatus& status) override {
    for (StatusObserver* observer : observers_) observer->cutter_changed(status);
  }
  void nesting_done(const NestingStatus& status) override {
    for (StatusObserver* observer : observers_) observer->nesting_done(status);
  }

 private:
  std::vector<StatusObserver*> observers_;
};

}  // namespace lastcut::daemon
