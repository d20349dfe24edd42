// A write-up (writeup.h) as bytes, both ways, and the request that makes one, so a write-up can be made in another copy
// of the program: the page makes it in its Web Worker for student code, which shares no memory with the page's
// thread, and draws its pictures on the page's thread.
//
//   request = encode_writeup_request(folder, files);      // the page: the student's files and the settings' files
//   Writeup made = make_requested_writeup(request);        // the worker: written there, then make_writeup
//   bytes = encode_writeup(made); decode_writeup(bytes);   // back to the page
//
// Invariants:
// - The bytes are CBOR (nlohmann::json's): strings go byte for byte and doubles keep their bits.
// - decode_writeup(encode_writeup(w)) is w for every field; meshes keep every record and id (core/mesh_records.h), so
//   a broken mesh a student's flip left draws as it was.
// - make_requested_writeup writes each file at its path (its folders made), then makes the write-up of the folder as
//   `meshedit writeup` does (grade/submission.h's Submission::read, writeup_settings.h's read_writeup_settings): the
//   same write-up for the same files.
// - Bytes that are not this CBOR, or miss a field, throw std::runtime_error saying which; nothing else is thrown but
//   std::bad_alloc (make_requested_writeup: and a file that cannot be written, as std::runtime_error).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "writeup/writeup.h"

namespace meshedit {

struct WriteupRequestFile {
  std::filesystem::path path;
  std::string bytes;
};

std::vector<uint8_t> encode_writeup_request(const std::filesystem::path& folder,
                                            const std::vector<WriteupRequestFile>& files);
Writeup make_requested_writeup(std::span<const uint8_t> request);

std::vector<uint8_t> encode_writeup(const Writeup& writeup);
Writeup decode_writeup(std::span<const uint8_t> bytes);

}  // namespace meshedit
