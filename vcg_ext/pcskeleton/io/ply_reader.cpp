#include "pcskeleton/io/ply_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>

namespace pcskeleton {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the binary PLY decoder assumes a little-endian host");

bool PlyElement::has(const std::string& property) const {
    return std::any_of(properties.begin(), properties.end(), [&](const PlyProperty& p) { return p.name == property; });
}

namespace {

std::size_t sizeOf(PlyType type) {
    switch (type) {
        case PlyType::Int8: case PlyType::UInt8: return 1;
        case PlyType::Int16: case PlyType::UInt16: return 2;
        case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
        case PlyType::Float64: return 8;
    }
    return 0;
}

bool isInteger(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

bool parseType(const std::string& name, PlyType& type) {
    static const std::map<std::string, PlyType> names = {
        {"char", PlyType::Int8},     {"int8", PlyType::Int8},      {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},    {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},  {"int", PlyType::Int32},
        {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},    {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64}};
    const auto found = names.find(name);
    if (found == names.end()) return false;
    type = found->second;
    return true;
}

std::vector<std::string> splitWords(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
};

PlyHeader readHeader(InputFile& file) {
    std::string line;
    if (!file.readLine(line) || line != "ply") file.fail("not a PLY file (the first line is not 'ply').");
    PlyHeader header;
    bool haveFormat = false;
    while (file.readLine(line)) {
        const std::vector<std::string> words = splitWords(line);
        if (words.empty()) continue;
        const std::string& keyword = words[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "end_header") {
            if (!haveFormat) file.failAtLine("the header has no 'format' line.");
            return header;
        }
        if (keyword == "format") {
            if (words.size() != 3) file.failAtLine("a format line reads 'format ascii 1.0' (or binary_little_endian, binary_big_endian).");
            if (words[1] == "ascii") header.format = PlyFormat::Ascii;
            else if (words[1] == "binary_little_endian") header.format = PlyFormat::BinaryLittleEndian;
            else if (words[1] == "binary_big_endian") header.format = PlyFormat::BinaryBigEndian;
            else file.failAtLine("unknown format '" + words[1] + "'.");
            haveFormat = true;
        } else if (keyword == "element") {
            if (words.size() != 3) file.failAtLine("an element line reads 'element NAME COUNT'.");
            const std::string& count = words[2];
            // Digits only: strtoull would take "-1" for 2^64 - 1.
            if (count.empty() || count.size() > 18 || count.find_first_not_of("0123456789") != std::string::npos) {
                file.failAtLine("the count of element '" + words[1] + "' is not a number below 10^18 ('" + count + "').");
            }
            header.elements.push_back({words[1], std::stoull(count), {}});
        } else if (keyword == "property") {
            if (header.elements.empty()) file.failAtLine("a property comes before any element.");
            PlyProperty property;
            bool known = false;
            if (words.size() == 5 && words[1] == "list") {
                property.isList = true;
                known = parseType(words[2], property.countType) && parseType(words[3], property.type);
                if (known && !isInteger(property.countType)) file.failAtLine("a list length must have an integer type.");
                property.name = words[4];
            } else if (words.size() == 3) {
                known = parseType(words[1], property.type);
                property.name = words[2];
            } else {
                file.failAtLine("a property line reads 'property TYPE NAME' or 'property list TYPE TYPE NAME'.");
            }
            if (!known) file.failAtLine("unknown property type in '" + line + "'.");
            header.elements.back().properties.push_back(property);
        } else {
            file.failAtLine("unknown header keyword '" + keyword + "'.");
        }
    }
    file.fail("the header ends without 'end_header'.");
}

// The fewest bytes one record of the element can take in the file.
std::uint64_t minimumRecordBytes(const PlyElement& element, PlyFormat format) {
    if (format == PlyFormat::Ascii) return 2 * element.properties.size();  // a digit and a separator each
    std::uint64_t bytes = 0;
    for (const PlyProperty& p : element.properties) bytes += sizeOf(p.isList ? p.countType : p.type);
    return bytes;
}

void checkCountAgainstSize(InputFile& file, const PlyElement& element, PlyFormat format) {
    if (element.count == 0) return;
    if (element.properties.empty()) {
        file.fail("element '" + element.name + "' declares " + std::to_string(element.count) +
                  " records but no property.");
    }
    const std::uint64_t perRecord = minimumRecordBytes(element, format);
    const std::uint64_t available = file.remaining() == std::numeric_limits<std::uint64_t>::max()
                                        ? file.remaining()
                                        : file.remaining() + 1;  // an ascii file may lack its last newline
    if (element.count > available / perRecord) {
        file.fail("element '" + element.name + "' declares " + std::to_string(element.count) +
                  " records of at least " + std::to_string(perRecord) + " bytes, but only " +
                  std::to_string(file.remaining()) + " bytes follow (byte offset " + std::to_string(file.offset()) +
                  "): the file is truncated or the count is wrong.");
    }
}

// Decodes one binary value of the given type, swapping bytes for big-endian files.
double decode(const unsigned char* bytes, PlyType type, bool swap) {
    unsigned char raw[8];
    const std::size_t n = sizeOf(type);
    if (swap) std::reverse_copy(bytes, bytes + n, raw);
    else std::memcpy(raw, bytes, n);
    switch (type) {
        case PlyType::Int8: { std::int8_t v; std::memcpy(&v, raw, 1); return v; }
        case PlyType::UInt8: { std::uint8_t v; std::memcpy(&v, raw, 1); return v; }
        case PlyType::Int16: { std::int16_t v; std::memcpy(&v, raw, 2); return v; }
        case PlyType::UInt16: { std::uint16_t v; std::memcpy(&v, raw, 2); return v; }
        case PlyType::Int32: { std::int32_t v; std::memcpy(&v, raw, 4); return v; }
        case PlyType::UInt32: { std::uint32_t v; std::memcpy(&v, raw, 4); return v; }
        case PlyType::Float32: { float v; std::memcpy(&v, raw, 4); return v; }
        case PlyType::Float64: { double v; std::memcpy(&v, raw, 8); return v; }
    }
    return 0.0;
}

// Reads the records of one element and hands the wanted values to `record` (may be null:
// the element is skipped, still checked).
class ElementDecoder {
public:
    ElementDecoder(InputFile& file, PlyFormat format, const PlyElement& element, const PlyElementReader* reader)
        : file_(file), format_(format), element_(element), reader_(reader),
          slotOf_(element.properties.size(), -1) {
        if (reader) {
            values_.assign(reader->properties.size(), std::numeric_limits<double>::quiet_NaN());
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const auto wanted = std::find(reader->properties.begin(), reader->properties.end(),
                                              element.properties[p].name);
                if (wanted != reader->properties.end() && !element.properties[p].isList) {
                    slotOf_[p] = int(wanted - reader->properties.begin());
                }
            }
        }
    }

    void readAll() {
        for (record_ = 0; record_ < element_.count; ++record_) {
            // An ascii record is one line: a line with more or fewer values than the header
            // declares is refused, where reading on would shift every later record.
            if (format_ == PlyFormat::Ascii) startRecordLine();
            for (std::size_t p = 0; p < element_.properties.size(); ++p) readProperty(p);
            if (format_ == PlyFormat::Ascii && line_.find_first_not_of(" \t", position_) != std::string::npos) {
                fail("the line holds more values than the header declares for one '" + element_.name + "' record.");
            }
            if (reader_ && reader_->record) reader_->record(values_.data());
        }
    }

private:
    std::string where() const {
        std::string place = format_ == PlyFormat::Ascii ? "line " + std::to_string(file_.lineNumber())
                                                        : "byte offset " + std::to_string(file_.offset());
        return "record " + std::to_string(record_) + " of element '" + element_.name + "' (" + place + ")";
    }
    [[noreturn]] void fail(const std::string& why) const { file_.fail(where() + ": " + why); }

    void readProperty(std::size_t p) {
        const PlyProperty& property = element_.properties[p];
        if (!property.isList) {
            const double value = readValue(property.type);
            if (slotOf_[p] >= 0) values_[std::size_t(slotOf_[p])] = value;
            return;
        }
        const double length = readValue(property.countType);
        if (length < 0) fail("list '" + property.name + "' has a negative length.");
        const std::uint64_t items = std::uint64_t(length);
        const std::uint64_t itemBytes = format_ == PlyFormat::Ascii ? 2 : sizeOf(property.type);
        if (items > (file_.remaining() + lineLeft()) / itemBytes + 1) {
            fail("list '" + property.name + "' claims " + std::to_string(items) + " items, more than the file holds.");
        }
        for (std::uint64_t i = 0; i < items; ++i) readValue(property.type);
    }

    double readValue(PlyType type) {
        if (format_ == PlyFormat::Ascii) return parseToken(nextToken(), type);
        unsigned char bytes[8];
        if (!file_.readBytes(bytes, sizeOf(type))) fail("the file ends here.");
        return decode(bytes, type, format_ == PlyFormat::BinaryBigEndian);
    }

    std::uint64_t lineLeft() const { return line_.size() - std::min(line_.size(), position_); }

    // The next line that is not blank.
    void startRecordLine() {
        do {
            if (!file_.readLine(line_)) fail("the file ends here.");
        } while (line_.find_first_not_of(" \t") == std::string::npos);
        position_ = 0;
    }

    std::string nextToken() {
        position_ = line_.find_first_not_of(" \t", position_);
        if (position_ == std::string::npos) {
            fail("the line holds fewer values than the header declares for one '" + element_.name + "' record.");
        }
        const std::size_t end = std::min(line_.find_first_of(" \t", position_), line_.size());
        std::string token = line_.substr(position_, end - position_);
        position_ = end;
        return token;
    }

    double parseToken(const std::string& token, PlyType type) {
        char* end = nullptr;
        errno = 0;
        if (isInteger(type)) {
            const long long value = std::strtoll(token.c_str(), &end, 10);
            if (end == token.c_str() || *end != '\0' || errno == ERANGE) fail("'" + token + "' is not an integer.");
            const double limit = std::ldexp(1.0, int(8 * sizeOf(type)));
            const bool isSigned = type == PlyType::Int8 || type == PlyType::Int16 || type == PlyType::Int32;
            if ((isSigned && (value < -limit / 2 || value >= limit / 2)) || (!isSigned && (value < 0 || value >= limit))) {
                fail(token + " is out of range for its type.");
            }
            return double(value);
        }
        double value = 0;
        if (!parseNumber(token.data(), token.data() + token.size(), value)) {
            fail("'" + token + "' is not a number" + decimalCommaHint(token) + ".");
        }
        return value;
    }

    InputFile& file_;
    PlyFormat format_;
    const PlyElement& element_;
    const PlyElementReader* reader_;
    std::vector<int> slotOf_;  // per property of the element: its place in values_, or -1
    std::vector<double> values_;
    std::uint64_t record_ = 0;
    std::string line_;
    std::size_t position_ = 0;
};

}  // namespace

void readPly(InputFile& file, const std::vector<PlyElementReader>& readers) {
    const PlyHeader header = readHeader(file);
    std::size_t last = 0;  // one past the last element somebody asked for
    for (std::size_t e = 0; e < header.elements.size(); ++e) {
        for (const PlyElementReader& reader : readers) {
            if (reader.element == header.elements[e].name) last = e + 1;
        }
    }
    for (std::size_t e = 0; e < last; ++e) {
        const PlyElement& element = header.elements[e];
        checkCountAgainstSize(file, element, header.format);
        const PlyElementReader* reader = nullptr;
        for (const PlyElementReader& r : readers) {
            if (r.element == element.name) reader = &r;
        }
        if (reader && reader->begin) reader->begin(element);
        ElementDecoder(file, header.format, element, reader).readAll();
    }
    // Lines after the last declared record mean that the header's counts are not the file's.
    if (header.format == PlyFormat::Ascii && last == header.elements.size()) {
        for (std::string line; file.readLine(line);) {
            if (line.find_first_not_of(" \t") != std::string::npos) {
                file.failAtLine("the file goes on after the last record the header declares (" +
                                (header.elements.empty() ? std::string("none")
                                                         : std::to_string(header.elements.back().count) + " of element '" +
                                                               header.elements.back().name + "'") +
                                "): the header's counts are wrong.");
            }
        }
    }
}

}  // namespace pcskeleton
