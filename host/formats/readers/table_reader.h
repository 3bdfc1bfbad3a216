// Reading back every table file the baker writes: OpenEXR (exr/table_file.h), KTX 2.0, DDS (DX10
// header), 16-bit PNG and the C header / ECMAScript module. `brdfbake info` and `brdfbake shader`
// take any of them. Written from the formats' specifications apart from the writers
// (formats/writers.h), so a writer's mistake is not mirrored here; the tests check these readers
// against the specification-checking ones in tests/ (ktx2_reader.h, dds_reader.h).
//
// The format is told by the file's first bytes, not its name. Errors: a missing, unreadable file or
// a directory throws Error(kExitNoInput, "cannot read PATH: <reason>"); a file that is not one of
// these formats, is truncated, or holds a field outside what the baker reads throws
// Error(kExitDataErr, "cannot read PATH: <format> <field and accepted values>"). (EXR files keep the
// EXR reader's errors, kExitNoInput for every failure.)
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "formats/storage.h"
#include "formats/table_image.h"

namespace brdfbake {

// A table file as read back.
struct TableFile {
  std::string path;
  FileFormat format = FileFormat::Exr;
  Precision precision = Precision::Float32;  // what each channel stores (EXR: float32 or float16)
  std::string storage;  // the file's own name for it: "VK_FORMAT_R16G16B16A16_SFLOAT", "DXGI_FORMAT_R32G32_FLOAT",
                        // "16-bit RGB", "float32 literals (C header)", EXR "FLOAT" / "HALF"
  int depth = 1;        // slices of a 3D texture (KTX2, DDS, header); 1 otherwise
  // width, height, channels (R, G, B, A as stored, padding included), planes (with pixels) as values,
  // [c][(z * height + y) * width + x], PNG's mapping applied; attributes: the EXR's, or from the text
  // metadata (tableHeaderFromText). A DDS has none.
  TableImage table;
  std::vector<std::pair<std::string, std::string>> text;  // text metadata as stored, in file order (KTX2
                                                          // key/value data, PNG tEXt, header attributes)
};

// The format of the file at `path` from its first bytes. Throws as above (kExitDataErr when none fits).
FileFormat detectTableFormat(const std::string& path);

// The whole file: size, storage, metadata and (when `pixels`) the values. Throws as above.
TableFile readTableFile(const std::string& path, bool pixels = true);

// The metadata `brdfbake shader` builds the code from: the file's own, or for a DDS (which has no
// place for it) that of a file beside it with the same stem (.ktx2, .exr, .png, .h, .mjs, in that
// order) whose size and texels match the DDS's within both files' storage rounding; brdf.format,
// brdf.precision, brdf.error and brdf.channels then describe the DDS. `*from` (when not null) gets
// that file's path, or "" for the file's own. Throws kExitDataErr for a DDS without such a file, and
// for a 3D texture (the generated code samples the EXR's atlas of a 3D table).
TableImage tableMetadata(const std::string& path, std::string* from = nullptr);
// The same for a DDS already read (`dds.format` must be Dds): the matching file beside it, or "" when
// there is none (then `*meta` is untouched).
std::string ddsMetadataFile(const TableFile& dds, TableImage* meta);

// `brdfbake info FILE` for any format (EXR: describeTableExr). Path, format and storage, size,
// channels, every metadata entry (one line each, sorted by name; EXR with its attribute types, the
// text formats as "(text)"), the range of each channel's values.
std::string describeTableFile(const TableFile& file);

// A header from text metadata (KTX2 key/value data, PNG text chunks, the header format's attribute
// table; formats/storage.h attributesAsText writes them): every attribute as a string, those that
// are all number also as floats, "brdf.<axis>.range" = "lo,hi" as a V2f.
TableImage tableHeaderFromText(int width, int height, const std::map<std::string, std::string>& attributes);

}  // namespace brdfbake
