#pragma once
// The parts of a job whose pieces are of several configured materials (issue 35, per-material
// batches; docs/cutting-pieces.md): the job is cut one material after another, each part nested and
// cut as a whole job of that material would be (a strip batch on its roll or sheet, or a hide), and
// the job is done when its last part is cut. While a part is nested and cut, the job's material,
// cutter and pieces are the part's; the store keeps the list and which part is current (the spool in
// state.json, the ledger in jobs.parts and jobs.part). A job of one material has no parts.
//
// Why one after another and not at once: the job keeps one stage and one batch at a time, the life
// cycle every feature of both stores is written against. The parts' order (job_parts in
// daemon/station/job_piece_rules.hpp) puts the rolls and sheets first, which are cut without waiting,
// so that the leather, which waits for a hide, is what the job waits for last.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lastcut::daemon {

struct JobPart {
  std::string material;  // a configured material's name
  std::string cutter;    // the cutter its batches go to
  int pieces = 0;        // the pieces to cut of this material (items x demand)
  // A part split over hides (split_part): the copies of each item of the material's items file this
  // part cuts, one entry per item of the file. Empty: every item with its own demand.
  std::vector<int> copies;
  bool operator==(const JobPart&) const = default;
};

// A hide took some of the current part's pieces (a ticket with split_over_hides): the copies of each
// item of the part's items file placed on the hide and left for the next one.
struct PartSplit {
  std::vector<int> placed, rest;  // one entry per item of the items file
  bool operator==(const PartSplit&) const = default;
};

nlohmann::json parts_to_json(const std::vector<JobPart>& parts);
// Entries that are not objects with a material are left out (a damaged file: the part is not cut,
// and the job ends after the parts it can read).
std::vector<JobPart> parts_from_json(const nlohmann::json& json);

// The parts once the current part is split: it becomes the placed pieces and the rest follows it as
// the next part, of the same material and cutter. A job of one material (no parts) gets two parts of
// `whole`'s material and cutter. The part index stays.
std::vector<JobPart> split_part(std::vector<JobPart> parts, int current, const JobPart& whole, const PartSplit& split);

// Where a job computed again (a requeue, a restart) goes on: the parts before the stored current part
// are cut and stay cut, so no piece is cut twice.
//  - The stored parts are the computed ones, some split over hides (split_part): the parts cut so far
//    are kept, and what is not cut yet of each material becomes one part again (a new hide may take
//    it whole). `part` is the first of those.
//  - Anything else (nothing stored, the style or the configuration changed the pieces, a damaged
//    list): the computed parts from the first.
// computed: the parts as computed now, empty for a job of one material, whose pieces `whole` names
// (material, cutter, pieces); the result's parts are then empty again unless some were cut.
struct ResumedParts {
  std::vector<JobPart> parts;
  int part = 0;
  bool operator==(const ResumedParts&) const = default;
};
ResumedParts resume_parts(const std::vector<JobPart>& stored, int stored_part, const std::vector<JobPart>& computed,
                          const JobPart& whole);

// "goes on with part 2 of 3: 3 pieces of leather (the parts before it are cut)": how the log and the
// job's events say where a job computed again goes on; "" when it starts at its first part.
std::string describe_resumed(const ResumedParts& resumed);

// "4 pieces of lining", "1 piece of leather": how every line names a part's pieces.
std::string pieces_of(int pieces, const std::string& material);

// The pieces `copies` counts (the sum).
int count_copies(const std::vector<int>& copies);

// The current part's copies (JobPart::copies); empty for a job of one material or a part not split.
std::vector<int> part_copies(const std::vector<JobPart>& parts, int current);

// "4 of 10 pieces of leather on hide H-7; 6 wait for the next hide": a split as the log and the
// job's events say it.
std::string describe_split(const PartSplit& split, const std::string& material, const std::string& hide);

// "4 pieces of lining on cutter-2, then 2 pieces of leather on cutter-1": the parts as the log and
// the report say them.
std::string describe_parts(const std::vector<JobPart>& parts);

// Which pieces wait for which material, for `lastcut status` and the operator page: "6 pieces of lining
// cut; 2 pieces of leather now; 4 pieces of felt next" (`current` is the part being nested or cut;
// `all_cut` for a job that is done). "" for a job of one material.
std::string parts_progress(const std::vector<JobPart>& parts, int current, bool all_cut);

}  // namespace lastcut::daemon
