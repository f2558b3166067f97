// fmt's compiled part, built into edsc instead of linked from libfmt.so.
//
// libfmt.so needs libstdc++.so, and loading and relocating those two costs
// every run of edsc more than the rest of its start-up (docs/performance.md).
// Built here, with the same flags as every other file (fmt::fmt's FMT_SHARED
// only sets symbol visibility on Linux), libstdc++ can be linked statically.
// The definitions are fmt's own (format-inl.h); the instantiations below are
// the ones fmt's headers declare and leave to the library.
#include <fmt/format-inl.h>

namespace fmt {
inline namespace v9 {
namespace detail {

template FMT_API auto thousands_sep_impl<char>(locale_ref) -> thousands_sep_result<char>;
template FMT_API auto decimal_point_impl<char>(locale_ref) -> char;
template FMT_API auto thousands_sep_impl<wchar_t>(locale_ref) -> thousands_sep_result<wchar_t>;
template FMT_API auto decimal_point_impl<wchar_t>(locale_ref) -> wchar_t;
template FMT_API void buffer<char>::append<char>(const char*, const char*);
template FMT_API void vformat_to<char>(buffer<char>&, basic_string_view<char>,
                                       basic_format_args<FMT_BUFFER_CONTEXT(char)>, locale_ref);
template FMT_API locale_ref::locale_ref(const std::locale&);
template FMT_API auto locale_ref::get<std::locale>() const -> std::locale;
template FMT_API auto dragonbox::to_decimal(float) noexcept -> dragonbox::decimal_fp<float>;
template FMT_API auto dragonbox::to_decimal(double) noexcept -> dragonbox::decimal_fp<double>;

}  // namespace detail
}  // namespace v9
}  // namespace fmt
