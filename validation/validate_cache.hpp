#pragma once
// Results shared between catalogue entries (one FE solve of the 32-magnet benchmark serves
// its three field components, one charge-model sweep serves torque and forces). The first
// entry that asks computes; entries running in parallel that ask for the same key wait for
// it. A computation that throws rethrows in every entry that asked.
#include <any>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace magfem {

class ComputeCache {
public:
  template <class T>
  std::shared_ptr<const T> get(const std::string& key, const std::function<T()>& compute) {
    std::promise<std::any> promise;
    std::shared_future<std::any> future;
    bool owner = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = items_.find(key);
      if (it == items_.end()) {
        future = promise.get_future().share();
        items_.emplace(key, future);
        owner = true;
      } else {
        future = it->second;
      }
    }
    if (owner) {
      try {
        promise.set_value(std::make_any<std::shared_ptr<const T>>(
            std::make_shared<const T>(compute())));
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return std::any_cast<std::shared_ptr<const T>>(future.get());
  }

private:
  std::mutex mutex_;
  std::map<std::string, std::shared_future<std::any>> items_;
};

} // namespace magfem
