#pragma once
// The named value members of each entity, in schema field order. Lowering
// fills them from the schema's field descriptors, the JSON emitter names them
// with the schema's field names, and a validator can walk them generically.
#include <array>

#include "model/device.hpp"

namespace edsc::model::slots {

template <class T>
using slot = value T::*;

inline constexpr std::array<slot<param>, 24> param{&param::reserved,
                                                   &param::link_path_size,
                                                   &param::link_path,
                                                   &param::descriptor,
                                                   &param::data_type,
                                                   &param::data_size,
                                                   &param::name,
                                                   &param::units,
                                                   &param::help,
                                                   &param::min,
                                                   &param::max,
                                                   &param::default_value,
                                                   &param::scaling_multiplier,
                                                   &param::scaling_divisor,
                                                   &param::scaling_base,
                                                   &param::scaling_offset,
                                                   &param::multiplier_link,
                                                   &param::divisor_link,
                                                   &param::base_link,
                                                   &param::offset_link,
                                                   &param::decimal_precision,
                                                   &param::international_name,
                                                   &param::international_units,
                                                   &param::international_help};

inline constexpr std::array<slot<io_data>, 7> io{&io_data::size, &io_data::significant_bits, &io_data::mask,
                                                 &io_data::name, &io_data::path_size,        &io_data::path,
                                                 &io_data::help};

inline constexpr std::array<slot<io_connection_info>, 3> io_conn{
    &io_connection_info::mask, &io_connection_info::default_input, &io_connection_info::default_output};

inline constexpr std::array<slot<assembly>, 6> assembly{&assembly::name,      &assembly::path,
                                                        &assembly::size,      &assembly::descriptor,
                                                        &assembly::reserved1, &assembly::reserved2};

inline constexpr std::array<slot<variant>, 6> variant{&variant::name,      &variant::help,      &variant::reserved1,
                                                      &variant::reserved2, &variant::reserved3, &variant::selector};

inline constexpr std::array<slot<array>, 10> array{
    &array::name,      &array::path,      &array::descriptor,   &array::help,         &array::reserved1,
    &array::reserved2, &array::reserved3, &array::element_size, &array::element_type, &array::dimensions};

inline constexpr std::array<slot<connection>, 17> connection{&connection::trigger,
                                                             &connection::params,
                                                             &connection::ot_rpi,
                                                             &connection::ot_size,
                                                             &connection::ot_format,
                                                             &connection::to_rpi,
                                                             &connection::to_size,
                                                             &connection::to_format,
                                                             &connection::proxy_config_size,
                                                             &connection::proxy_config_format,
                                                             &connection::target_config_size,
                                                             &connection::target_config_format,
                                                             &connection::name,
                                                             &connection::help,
                                                             &connection::path,
                                                             &connection::safety_async,
                                                             &connection::safety_max_consumers};

inline constexpr std::array<slot<port>, 4> port{&port::type, &port::name, &port::path, &port::port_number};

inline constexpr std::array<slot<tspec>, 3> tspec{&tspec::direction, &tspec::size, &tspec::rate};

inline constexpr std::array<slot<rack>, 8> rack{&rack::vendor,         &rack::product_type,   &rack::product_code,
                                                &rack::major_revision, &rack::minor_revision, &rack::reserved1,
                                                &rack::reserved2,      &rack::reserved3};

inline constexpr std::array<slot<group>, 2> group{&group::name, &group::count};

}  // namespace edsc::model::slots
