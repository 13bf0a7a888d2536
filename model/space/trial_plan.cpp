#include "model/space/trial_plan.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::space {
namespace {

constexpr const char* kTrialHeader = "trial,stage,reference,left,right[,chosen]";

// A triplet's identity: reference and the candidate pair with a < b.
using Key = std::tuple<std::size_t, std::size_t, std::size_t>;

Key key_of(std::size_t reference, std::size_t x, std::size_t y) {
  return {reference, std::min(x, y), std::max(x, y)};
}

io::Triplet triplet_of(const Key& key) {
  io::Triplet t;
  std::tie(t.reference, t.a, t.b) = key;
  return t;
}

// Every key `repetitions` times, shuffled. Pairs of presentations show each candidate on the left
// once; the one extra presentation of an odd count is oriented along walks of the multigraph whose
// edges are the keys' candidate pairs: starting each walk at a vertex of odd remaining degree (when
// there is one) makes every vertex balanced except the two ends of each walk, and each odd vertex
// ends exactly one walk, so every stimulus is left as often as right ±1 (Euler's argument).
std::vector<Trial> plan_keys(const std::vector<Key>& keys, int repetitions, int stage,
                             std::mt19937_64& generator) {
  std::vector<Trial> trials;
  trials.reserve(keys.size() * static_cast<std::size_t>(repetitions));
  for (const auto& [r, a, b] : keys)
    for (int k = 0; k < repetitions / 2; ++k) {
      trials.push_back({r, a, b, stage});
      trials.push_back({r, b, a, stage});
    }
  if (repetitions % 2 == 1 && !keys.empty()) {
    std::size_t vertices = 0;
    for (const auto& [r, a, b] : keys) vertices = std::max({vertices, r + 1, a + 1, b + 1});
    std::vector<std::vector<std::size_t>> incident(vertices);
    for (std::size_t e = 0; e < keys.size(); ++e) {
      incident[std::get<1>(keys[e])].push_back(e);
      incident[std::get<2>(keys[e])].push_back(e);
    }
    // Shuffled so that which stimulus gets the +1 and which edges chain up is not fixed by index.
    for (auto& list : incident) std::shuffle(list.begin(), list.end(), generator);
    std::vector<std::size_t> remaining(vertices), next(vertices, 0);
    for (std::size_t v = 0; v < vertices; ++v) remaining[v] = incident[v].size();
    std::vector<bool> used(keys.size(), false);
    std::size_t left_to_orient = keys.size();
    while (left_to_orient > 0) {
      std::size_t start = vertices;
      for (std::size_t v = 0; v < vertices && start == vertices; ++v)
        if (remaining[v] % 2 == 1) start = v;
      for (std::size_t v = 0; v < vertices && start == vertices; ++v)
        if (remaining[v] > 0) start = v;
      std::size_t v = start;
      for (;;) {
        while (next[v] < incident[v].size() && used[incident[v][next[v]]]) ++next[v];
        if (next[v] == incident[v].size()) break;
        const std::size_t e = incident[v][next[v]];
        used[e] = true;
        --left_to_orient;
        const auto& [r, a, b] = keys[e];
        const std::size_t u = v == a ? b : a;
        trials.push_back({r, v, u, stage});
        --remaining[v];
        --remaining[u];
        v = u;
      }
    }
  }
  std::shuffle(trials.begin(), trials.end(), generator);
  return trials;
}

void check_repetitions(int repetitions) {
  if (repetitions < 1)
    throw std::invalid_argument("a trial plan needs at least one repetition per triplet, found " +
                                std::to_string(repetitions));
}

bool storable(const std::string& text) {
  return !text.empty() && text.find_first_of(",\n\r") == std::string::npos;
}

}  // namespace

std::size_t triplet_count(std::size_t n) { return n < 3 ? 0 : n * (n - 1) * (n - 2) / 2; }

std::vector<io::Triplet> all_triplets(std::size_t n) {
  std::vector<io::Triplet> all;
  all.reserve(triplet_count(n));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        if (a != r && b != r) all.push_back(triplet_of({r, a, b}));
  return all;
}

std::vector<Trial> plan_all_triplets(std::size_t stimuli, int repetitions, std::uint64_t seed,
                                     double fraction) {
  if (stimuli < 3)
    throw std::invalid_argument("a triplet plan needs at least 3 stimuli, found " +
                                std::to_string(stimuli));
  check_repetitions(repetitions);
  if (!(fraction > 0 && fraction <= 1))
    throw std::invalid_argument("the fraction of triplets in stage 1 must be in (0, 1], found " +
                                std::to_string(fraction));
  std::mt19937_64 generator(seed);
  std::vector<Key> keys;
  for (const io::Triplet& t : all_triplets(stimuli)) keys.emplace_back(t.reference, t.a, t.b);
  if (fraction < 1) {
    const auto wanted = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::llround(fraction * static_cast<double>(keys.size()))));
    std::shuffle(keys.begin(), keys.end(), generator);
    keys.resize(std::min(wanted, keys.size()));
  }
  return plan_keys(keys, repetitions, 1, generator);
}

std::vector<io::Triplet> merge_trials(const std::vector<Trial>& trials,
                                      const std::vector<Choice>& choices, int stage) {
  if (choices.size() != trials.size())
    throw std::invalid_argument("merge_trials: " + std::to_string(trials.size()) + " trials but " +
                                std::to_string(choices.size()) + " choices");
  std::map<Key, io::Triplet> counts;
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const Trial& t = trials[i];
    if (stage != 0 && t.stage != stage) continue;
    if (choices[i] == Choice::none) continue;
    if (t.reference == t.left || t.reference == t.right || t.left == t.right)
      throw std::invalid_argument("merge_trials: trial " + std::to_string(i + 1) +
                                  " does not show three different stimuli");
    const Key key = key_of(t.reference, t.left, t.right);
    auto [it, inserted] = counts.try_emplace(key, triplet_of(key));
    const std::size_t chosen = choices[i] == Choice::left ? t.left : t.right;
    ++(chosen == it->second.a ? it->second.count_a : it->second.count_b);
  }
  std::vector<io::Triplet> merged;
  merged.reserve(counts.size());
  for (auto& [key, triplet] : counts) merged.push_back(std::move(triplet));
  return merged;
}

bool is_tie(const io::Triplet& t, const TieRule& rule) {
  return t.count_a + t.count_b > 0 && std::abs(t.count_a - t.count_b) <= rule.max_difference;
}

std::vector<io::Triplet> select_ties(const std::vector<io::Triplet>& stage_one,
                                     const TieRule& rule) {
  std::vector<io::Triplet> ties;
  for (const io::Triplet& t : stage_one)
    if (is_tie(t, rule)) ties.push_back(t);
  return ties;
}

std::vector<Trial> plan_stage_two(const std::vector<io::Triplet>& ties, int repetitions,
                                  std::uint64_t seed, std::size_t max_triplets) {
  check_repetitions(repetitions);
  std::mt19937_64 generator(seed);
  std::vector<Key> keys;
  std::set<Key> seen;
  for (const io::Triplet& t : ties) {
    const Key key = key_of(t.reference, t.a, t.b);
    if (seen.insert(key).second) keys.push_back(key);  // a tie listed twice is repeated once
  }
  if (max_triplets > 0 && keys.size() > max_triplets) {
    std::shuffle(keys.begin(), keys.end(), generator);
    keys.resize(max_triplets);
  }
  return plan_keys(keys, repetitions, 2, generator);
}

std::vector<io::Triplet> two_stage_counts(const std::vector<io::Triplet>& stage_one,
                                          const std::vector<io::Triplet>& stage_two,
                                          const TieRule& rule) {
  std::map<Key, io::Triplet> selected;
  for (const io::Triplet& t : stage_two) {
    io::Triplet canonical = t;
    if (t.a > t.b) {
      std::swap(canonical.a, canonical.b);
      std::swap(canonical.count_a, canonical.count_b);
    }
    auto [it, inserted] = selected.try_emplace(key_of(t.reference, t.a, t.b), canonical);
    if (!inserted) {
      it->second.count_a += canonical.count_a;
      it->second.count_b += canonical.count_b;
    }
  }
  std::vector<io::Triplet> kept;
  for (const io::Triplet& t : stage_one) {
    if (is_tie(t, rule) || t.count_a + t.count_b == 0) continue;
    if (selected.count(key_of(t.reference, t.a, t.b))) continue;
    kept.push_back(t);
  }
  std::vector<io::Triplet> merged;
  merged.reserve(selected.size() + kept.size());
  for (auto& [key, triplet] : selected) merged.push_back(std::move(triplet));
  merged.insert(merged.end(), kept.begin(), kept.end());
  std::sort(merged.begin(), merged.end(), [](const io::Triplet& x, const io::Triplet& y) {
    return key_of(x.reference, x.a, x.b) < key_of(y.reference, y.a, y.b);
  });
  return merged;
}

void write_trial_csv(const std::filesystem::path& file, const TrialList& list) {
  for (std::size_t s = 0; s < list.stimuli.size(); ++s)
    if (!storable(list.stimuli[s]))
      throw io::FormatError(file, "stimulus " + std::to_string(s),
                            "expected a non-empty name without ',' or line breaks, found " +
                                io::in_quotes(list.stimuli[s]));
  if (!list.choices.empty() && list.choices.size() != list.trials.size())
    throw io::FormatError(file, "",
                          "expected one choice per trial (" + std::to_string(list.trials.size()) +
                              "), found " + std::to_string(list.choices.size()));
  std::string text = "trial,stage,reference,left,right,chosen\n";
  for (std::size_t i = 0; i < list.trials.size(); ++i) {
    const Trial& t = list.trials[i];
    const std::string place = "trial " + std::to_string(i + 1);
    for (std::size_t index : {t.reference, t.left, t.right})
      if (index >= list.stimuli.size())
        throw io::FormatError(file, place,
                              "stimulus index " + std::to_string(index) + " out of range (" +
                                  std::to_string(list.stimuli.size()) + " stimuli)");
    if (t.reference == t.left || t.reference == t.right || t.left == t.right)
      throw io::FormatError(file, place, "expected three different stimuli");
    if (t.stage < 1)
      throw io::FormatError(file, place, "expected a stage >= 1, found " + std::to_string(t.stage));
    const Choice c = list.choices.empty() ? Choice::none : list.choices[i];
    text += std::to_string(i + 1) + ',' + std::to_string(t.stage) + ',' +
            list.stimuli[t.reference] + ',' + list.stimuli[t.left] + ',' + list.stimuli[t.right] +
            ',' +
            (c == Choice::left    ? "left"
             : c == Choice::right ? "right"
                                  : "") +
            '\n';
  }
  io::write_file_atomically(file, text);
}

TrialList read_trial_csv(const std::filesystem::path& file,
                         const std::vector<std::string>& stimuli, int last_stage) {
  io::CsvReader csv(file, kTrialHeader);
  const auto& header = csv.header();
  const std::size_t c_trial = header.column("trial"), c_stage = header.column("stage");
  const std::size_t names[] = {header.column("reference"), header.column("left"),
                               header.column("right")};
  const char* name_columns[] = {"reference", "left", "right"};
  const auto c_chosen = header.find("chosen");
  std::size_t needed = std::max({c_trial, c_stage, names[0], names[1], names[2]}) + 1;
  if (c_chosen) needed = std::max(needed, *c_chosen + 1);

  TrialList list;
  list.stimuli = stimuli;
  std::unordered_map<std::string, std::size_t> index_of;
  for (std::size_t s = 0; s < stimuli.size(); ++s) index_of.emplace(stimuli[s], s);
  std::unordered_set<long long> numbers;
  std::vector<std::string_view> fields;
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    csv.require_fields(fields, needed);
    const long long number = io::parse_integer(fields[c_trial], file, line, "trial");
    if (number < 1)
      throw io::FormatError(file, io::field_place(line, "trial"),
                            "expected a trial number >= 1, found " + std::to_string(number));
    if (!numbers.insert(number).second)
      throw io::FormatError(file, io::field_place(line, "trial"),
                            "trial " + std::to_string(number) + " appears twice");
    const long long stage = io::parse_integer(fields[c_stage], file, line, "stage");
    if (stage < 1 || stage > last_stage)
      throw io::FormatError(file, io::field_place(line, "stage"),
                            (last_stage == INT_MAX ? "expected a stage >= 1"
                                                   : "expected a stage 1 to " + std::to_string(last_stage)) +
                                std::string(", found ") + std::to_string(stage));
    std::size_t indices[3] = {};
    for (int k = 0; k < 3; ++k) {
      const std::string name(fields[names[k]]);
      if (name.empty())
        throw io::FormatError(file, io::field_place(line, name_columns[k]),
                              "expected a stimulus name, found an empty field");
      auto it = index_of.find(name);
      if (it == index_of.end()) {
        if (!stimuli.empty())
          throw io::FormatError(file, io::field_place(line, name_columns[k]),
                                "unknown stimulus " + io::in_quotes(name) +
                                    " (expected one of the " + std::to_string(stimuli.size()) +
                                    " stimuli of the plan)");
        it = index_of.emplace(name, list.stimuli.size()).first;
        list.stimuli.push_back(name);
      }
      indices[k] = it->second;
    }
    if (indices[0] == indices[1] || indices[0] == indices[2] || indices[1] == indices[2])
      throw io::FormatError(
          file, io::line_place(line),
          "expected three different stimuli, found " + io::in_quotes(fields[names[0]]) + ", " +
              io::in_quotes(fields[names[1]]) + ", " + io::in_quotes(fields[names[2]]));
    Choice choice = Choice::none;
    if (c_chosen) {
      const std::string_view chosen = fields[*c_chosen];
      if (chosen == "left") {
        choice = Choice::left;
      } else if (chosen == "right") {
        choice = Choice::right;
      } else if (!chosen.empty()) {
        throw io::FormatError(file, io::field_place(line, "chosen"),
                              "expected left, right or an empty field (not answered yet), found " +
                                  io::in_quotes(chosen));
      }
    }
    list.trials.push_back({indices[0], indices[1], indices[2], static_cast<int>(stage)});
    list.choices.push_back(choice);
  }
  return list;
}

}  // namespace nibrig::model::space
