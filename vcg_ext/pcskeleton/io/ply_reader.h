// A streaming PLY reader that checks everything before it uses it: ascii, binary little
// and big endian; every scalar type (char ... double, int8 ... float64); list properties
// of any element. Declared counts are checked against the bytes left in the file before
// anything is allocated for them, and list lengths before anything is skipped, so a
// crafted header cannot make it overflow, allocate terabytes or loop for ever. Errors
// name the header line or the byte offset (binary) / line (ascii) where the data is wrong.
//
// Why not vcglib's reader: it trusts the file (a list length from a binary file overflows
// a stack buffer), does not swap doubles in big-endian files and holds the whole mesh.
#pragma once

#include "pcskeleton/io/input_file.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pcskeleton {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;  // of a list: its items
    bool isList = false;
    PlyType countType = PlyType::UInt8;  // of a list: its length
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    bool has(const std::string& property) const;
};

// What a caller wants from one element: the values of some scalar properties, record by
// record, in the order asked for (NaN for a property the element lacks).
struct PlyElementReader {
    std::string element;
    std::vector<std::string> properties;
    // Called once with the header's description of the element, before its records: the
    // place to refuse a missing property or to reserve memory for element.count records
    // (the count has been checked against the file's size by then).
    std::function<void(const PlyElement&)> begin;
    std::function<void(const double* values)> record;
};

// Reads the header, then the elements in file order up to the last one a reader asks for
// (later elements, such as the faces of a mesh read for its vertices, are not read).
// Elements nobody asks for are skipped, their list lengths still checked.
void readPly(InputFile& file, const std::vector<PlyElementReader>& readers);

}  // namespace pcskeleton
