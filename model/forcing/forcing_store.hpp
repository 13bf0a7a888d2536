// Forcing models a lab calibrated (a material or surface of its own) and keeps by name: the user
// store's kind "forcing" (model/io/user_store.hpp), beside the bundled catalog's model in the
// user cache and never over it, so that `--forcing NAME` finds a lab's model wherever a command
// takes a forcing file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::forcing {

// $NIBRIG_FORCING_MODELS, else $XDG_DATA_HOME/nibrig/forcing, else ~/.local/share/nibrig/forcing.
std::filesystem::path forcing_store_folder();
// <folder>/<name>.json (the name made safe for a file name).
std::filesystem::path forcing_store_path(const std::string& name);

// The names of the models stored, sorted (none when the folder does not exist).
std::vector<std::string> stored_forcing_models();

// `name_or_file` itself when it is a file; else the model stored under that name. Throws
// std::invalid_argument naming both places and the names stored when it is neither.
std::filesystem::path find_forcing_model(const std::string& name_or_file);

// Throws what save_forcing_model throws for a name that cannot be saved, before any work is done.
void check_can_save(const std::string& name, bool replace = false);

// Writes `model` under `name` (the folder made when missing) and returns the file. Throws
// std::invalid_argument when a model of that name is stored and `replace` is false, or the name is
// empty.
std::filesystem::path save_forcing_model(const std::string& name, const ForcingModel& model,
                                         bool replace = false);

}  // namespace nibrig::model::forcing
