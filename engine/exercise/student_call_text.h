// A student call (student_call.h) and its result as bytes, both ways, so the call can run in another copy of the
// program: the page runs student code in a Web Worker, which shares no memory with the page's thread.
//
// Invariants:
// - The bytes are CBOR (RFC 8949, nlohmann::json's): strings go byte for byte (a file that is not UTF-8 too) and
//   doubles keep their bits (NaN and the infinities too).
// - decode(encode(x)) is x for every field: meshes keep every record and id (core/mesh_records.h), elements keep
//   their kind even when null. An outcome's validation is computed again from its mesh when decoded (validate() is a
//   function of the mesh).
// - The exercise goes by name; decoding finds it in the process's registry (exercise_registry.h), so both sides must
//   have registered the same scripted exercises. A name the registry does not know is an error naming it.
// - Bytes that are not this CBOR, or miss a field, throw std::runtime_error saying which; nothing else is thrown
//   but std::bad_alloc.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "exercise/student_call.h"

namespace meshedit {

std::vector<uint8_t> encode_student_call(const StudentCall& call);
StudentCall decode_student_call(std::span<const uint8_t> bytes);

std::vector<uint8_t> encode_student_call_result(const StudentCallResult& result);
StudentCallResult decode_student_call_result(std::span<const uint8_t> bytes);

}  // namespace meshedit
