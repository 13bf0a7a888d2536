#include "model/forcing/forcing_store.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/forcing/forcing_file.hpp"
#include "model/io/user_store.hpp"

namespace nibrig::model::forcing {

std::filesystem::path forcing_store_folder() {
  return io::user_store_folder("NIBRIG_FORCING_MODELS", "forcing");
}

std::filesystem::path forcing_store_path(const std::string& name) {
  return io::user_store_file(forcing_store_folder(), name, "forcing");
}

std::vector<std::string> stored_forcing_models() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(forcing_store_folder(), error))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::filesystem::path find_forcing_model(const std::string& name_or_file) {
  if (std::filesystem::is_regular_file(name_or_file)) return name_or_file;
  if (!name_or_file.empty()) {
    const auto stored = forcing_store_path(name_or_file);
    if (std::filesystem::is_regular_file(stored)) return stored;
  }
  std::string known;
  for (const auto& name : stored_forcing_models()) known += (known.empty() ? "" : ", ") + name;
  throw std::invalid_argument(
      "no forcing model file '" + name_or_file + "' and no model stored under that name in " +
      forcing_store_folder().string() +
      (known.empty() ? " (none stored yet: `nibrig forcing calibrate-material --save NAME`)"
                     : " (stored: " + known + ")"));
}

void check_can_save(const std::string& name, bool replace) {
  if (name.empty()) throw std::invalid_argument("saving a forcing model: no name given");
  const auto file = forcing_store_path(name);
  if (!replace && std::filesystem::exists(file))
    throw std::invalid_argument("a forcing model named '" + name + "' is stored already (" +
                                file.string() + "): choose another name, or replace it");
}

std::filesystem::path save_forcing_model(const std::string& name, const ForcingModel& model,
                                         bool replace) {
  check_can_save(name, replace);
  const auto file = forcing_store_path(name);
  std::filesystem::create_directories(file.parent_path());
  write_forcing_model(file, model);
  return file;
}

}  // namespace nibrig::model::forcing
