#pragma once
// The names DXF-AAMA gives things, shared by the writer and the reader of aama_dxf.hpp: the
// numbered layers and the keys of the piece and style "system text" (TEXT "Key: value" on layer 1).
namespace lastcut::aama {

inline constexpr const char* kBoundaryLayer = "1";  // the cut line and the system texts
inline constexpr const char* kNotchLayer = "4";
inline constexpr const char* kGrainLayer = "7";
inline constexpr const char* kInternalLayer = "8";  // drawn, not cut
inline constexpr const char* kSewLayer = "14";      // drawn, not cut

inline constexpr const char* kPieceNameKey = "Piece Name";
inline constexpr const char* kQuantityKey = "Quantity";
inline constexpr const char* kSizeKey = "Size";
inline constexpr const char* kStyleNameKey = "Style Name";
inline constexpr const char* kCategoryKey = "Category";
inline constexpr const char* kAnnotationKey = "Annotation";
inline constexpr const char* kUnitsKey = "Units";
inline constexpr const char* kMetricUnits = "METRIC";  // what the writer says: millimetres

}  // namespace lastcut::aama
