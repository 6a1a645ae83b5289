#include "basis/polyhedral/masks.hpp"

#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "basis/polyhedral/bezier.hpp"
#include "basis/polyhedral/configuration.hpp"
#include "basis/polyhedral/ngon_cap.hpp"
#include "basis/polyhedral/polar_cap.hpp"
#include "basis/polyhedral/star_cap.hpp"
#include "basis/polyhedral/tjunction_cap.hpp"
#include "core/error.hpp"

namespace iga::basis::polyhedral {
namespace {

ConfigurationMask derive(Configuration c, int valence) {
  ConfigurationMask m;
  switch (c) {
    case Configuration::Regular:
      m.configuration = c;
      m.valence = 4;
      m.gathered = 9;
      m.patches.push_back(regular_mask());
      break;
    case Configuration::Star:
      try {
        m = star_mask(valence);
      } catch (const std::exception& e) {
        throw UnsupportedError("polyhedral splines: no mask for a star of valence " + std::to_string(valence) + " (" +
                               e.what() + ")");
      }
      break;
    case Configuration::NGon:
      try {
        m = ngon_mask(valence);
      } catch (const std::exception& e) {
        throw UnsupportedError("polyhedral splines: no mask for an n-gon with n = " + std::to_string(valence) + " (" +
                               e.what() + ")");
      }
      break;
    case Configuration::Polar:
      try {
        m = polar_mask(valence);
      } catch (const std::exception& e) {
        throw UnsupportedError("polyhedral splines: no mask for a polar configuration of valence " +
                               std::to_string(valence) + " (" + e.what() + ")");
      }
      break;
    case Configuration::T0:
      try {
        m = t0_mask();
      } catch (const std::exception& e) {
        throw UnsupportedError(std::string("polyhedral splines: no mask for the T0 configuration (") + e.what() + ")");
      }
      break;
    case Configuration::T1:
      try {
        m = t1_mask();
      } catch (const std::exception& e) {
        throw UnsupportedError(std::string("polyhedral splines: no mask for the T1 configuration (") + e.what() + ")");
      }
      break;
    case Configuration::T2:
      try {
        m = t2_mask();
      } catch (const std::exception& e) {
        throw UnsupportedError(std::string("polyhedral splines: no mask for the T2 configuration (") + e.what() + ")");
      }
      break;
    default:
      throw UnsupportedError("polyhedral splines: the " + to_string(c) + " configuration (valence " +
                             std::to_string(valence) + ") has no mask in this build yet");
  }
  return m;
}

template <class F>
const ConfigurationMask& cached(std::map<std::pair<int, int>, ConfigurationMask>& cache, std::mutex& mutex,
                                Configuration c, int valence, F&& make) {
  const std::lock_guard<std::mutex> lock(mutex);
  const auto key = std::make_pair(static_cast<int>(c), valence);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, make()).first;
  return it->second;
}

}  // namespace

bool has_mask(Configuration c, int valence) {
  switch (c) {
    case Configuration::Regular: return true;
    case Configuration::Star:
    case Configuration::NGon: return valence == 3 || (valence >= 5 && valence <= 8);
    case Configuration::Polar: return valence >= 3 && valence <= 8;
    case Configuration::T0:
    case Configuration::T1:
    case Configuration::T2: return true;
    default: return false;
  }
}

const ConfigurationMask& native_mask(Configuration c, int valence) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, ConfigurationMask> cache;
  return cached(cache, mutex, c, valence, [&] { return derive(c, valence); });
}

const ConfigurationMask& bicubic_mask(Configuration c, int valence) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, ConfigurationMask> cache;
  return cached(cache, mutex, c, valence, [&] {
    ConfigurationMask m = native_mask(c, valence);
    for (PatchMask& p : m.patches) p = elevate(p, 3, 3);
    return m;
  });
}

}  // namespace iga::basis::polyhedral
