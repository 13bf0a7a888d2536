#include "rig/pen/tablet_model_name.hpp"

// libwacom's header declares C functions without extern "C".
extern "C" {
#include <libwacom/libwacom.h>
}

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

namespace nibrig::rig::pen {
namespace {

std::string maker_key(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The makers of the models sharing an id, by the first word of their names ("Huion H640P",
// "GAOMON S620"), each spelt as most of its entries spell it: "GAOMON or Huion".
std::string makers_of(const std::set<std::string>& models) {
  std::map<std::string, std::map<std::string, int>> spellings;  // lower-case maker → spelling → count
  for (const auto& model : models) {
    const std::string word = model.substr(0, model.find(' '));
    ++spellings[maker_key(word)][word];
  }
  std::string text;
  std::size_t i = 0;
  for (const auto& [key, counts] : spellings) {
    const auto most = std::max_element(counts.begin(), counts.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    text += (i == 0 ? "" : i + 1 == spellings.size() ? " or " : ", ") + most->first;
    ++i;
  }
  return text;
}

}  // namespace

TabletModelName name_tablet_model(const std::vector<LibwacomMatch>& matches_for_id, const std::string& device_name,
                                  std::uint16_t vendor, std::uint16_t product) {
  TabletModelName result;
  if (matches_for_id.empty()) return result;
  auto told = [&](const LibwacomMatch& m) {
    result.model = m.model;
    result.told_apart = true;
    result.width_mm = m.width_mm;
    result.height_mm = m.height_mm;
    return result;
  };
  // The device's own name, as libwacom matches it (the whole name, as the kernel gives it).
  std::set<std::string> named;
  for (const auto& m : matches_for_id) {
    if (!m.device_name.empty() && m.device_name == device_name) named.insert(m.model);
  }
  if (named.size() == 1) {
    for (const auto& m : matches_for_id) {
      if (m.model == *named.begin()) return told(m);
    }
  }
  // Else the id alone, when libwacom lists it, for any name, for one model only.
  std::set<std::string> models;
  const LibwacomMatch* any_name = nullptr;
  for (const auto& m : matches_for_id) {
    models.insert(m.model);
    if (m.device_name.empty()) any_name = &m;
  }
  if (models.size() == 1 && named.empty() && any_name) return told(*any_name);
  char id[16];
  std::snprintf(id, sizeof id, "%04x:%04x", vendor, product);
  result.model = "a " + makers_of(named.size() > 1 ? named : models) + " tablet (model not told apart by its USB id " +
                 id + ")";
  return result;
}

std::vector<LibwacomMatch> libwacom_usb_matches(std::uint16_t vendor, std::uint16_t product) {
  std::vector<LibwacomMatch> found;
  WacomDeviceDatabase* db = libwacom_database_new();
  if (!db) return found;
  if (WacomDevice** devices = libwacom_list_devices_from_database(db, nullptr)) {
    for (WacomDevice** d = devices; *d; ++d) {
      const char* model = libwacom_get_name(*d);
      const WacomMatch** matches = libwacom_get_matches(*d);
      for (const WacomMatch** m = matches; m && *m; ++m) {
        if (libwacom_match_get_bustype(*m) != WBUSTYPE_USB || libwacom_match_get_vendor_id(*m) != vendor ||
            libwacom_match_get_product_id(*m) != product) {
          continue;
        }
        const char* name = libwacom_match_get_name(*m);
        found.push_back({model ? model : "", name ? name : "", 25.4 * libwacom_get_width(*d),
                         25.4 * libwacom_get_height(*d)});
      }
    }
    std::free(devices);
  }
  libwacom_database_destroy(db);
  // The database's order is its hash table's: sorted, the same every run.
  std::sort(found.begin(), found.end(), [](const LibwacomMatch& a, const LibwacomMatch& b) {
    return a.model != b.model ? a.model < b.model : a.device_name < b.device_name;
  });
  return found;
}

}  // namespace nibrig::rig::pen
