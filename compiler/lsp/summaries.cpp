#include "lsp/summaries.hpp"

namespace edsc::lsp {

std::string_view summary_of(const schema::keyword_desc& k) {
  using schema::entry_id;
  switch (k.id) {
    case entry_id::desc_text: return "Free text describing the EDS file.";
    case entry_id::create_date: return "Date the file was created (mm-dd-yyyy).";
    case entry_id::create_time: return "Time the file was created (hh:mm:ss).";
    case entry_id::mod_date: return "Date the file was last modified (mm-dd-yyyy).";
    case entry_id::mod_time: return "Time the file was last modified (hh:mm:ss).";
    case entry_id::file_revision: return "Revision of the EDS file itself (major.minor), not of the device.";
    case entry_id::home_url: return "Where the newest version of this EDS can be downloaded.";
    case entry_id::exclude: return "Which tools may not write the file (NONE, WRITE, READ_WRITE).";
    case entry_id::eds_file_crc: return "Checksum of the file's contents, written by tools.";
    case entry_id::vend_code: return "Vendor ID (Identity attribute 1) assigned by ODVA.";
    case entry_id::vend_name: return "The vendor's name.";
    case entry_id::prod_type: return "Device type (Identity attribute 2), e.g. 12 communications adapter.";
    case entry_id::prod_type_str: return "The device type in words.";
    case entry_id::prod_code: return "Product code (Identity attribute 3), chosen by the vendor.";
    case entry_id::maj_rev: return "Major revision of the device this file describes (Identity attribute 4).";
    case entry_id::min_rev: return "Minor revision of the device this file describes (Identity attribute 4).";
    case entry_id::prod_name: return "Product name (Identity attribute 7).";
    case entry_id::catalog: return "Catalog number of the product.";
    case entry_id::icon: return "File name of the device's icon.";
    case entry_id::icon_contents: return "The icon itself, Base64-encoded.";
    case entry_id::application_profiles_assembly: return "Assembly of the device's application profile.";
    case entry_id::class_n: return "A network (and profile) the device belongs to.";
    case entry_id::io_default: return "DeviceNet I/O connection types used by default (a mask of the *Info types).";
    case entry_id::poll_info: return "Polled I/O: connection types it can combine with, default InputN and OutputN.";
    case entry_id::strobe_info:
      return "Bit-strobed I/O: connection types it can combine with, default InputN and OutputN.";
    case entry_id::cos_info:
      return "Change-of-state I/O: connection types it can combine with, default InputN and OutputN.";
    case entry_id::cyclic_info: return "Cyclic I/O: connection types it can combine with, default InputN and OutputN.";
    case entry_id::input_n: return "Data the device produces on a DeviceNet I/O connection: size, bits, path.";
    case entry_id::input_exa_n:
      return "A DeviceNet input data set whose size may come from a parameter (`ParamN:offset` members).";
    case entry_id::output_exa_n:
      return "A DeviceNet output data set whose size may come from a parameter (`ParamN:offset` members).";
    case entry_id::output_n: return "Data the device consumes on a DeviceNet I/O connection: size, bits, path.";
    case entry_id::pc_max_inst: return "Number of Parameter Object instances.";
    case entry_id::pc_descriptor: return "Parameter Object class descriptor bits.";
    case entry_id::pc_cfg_assembly: return "Configuration assembly instance (0: none).";
    case entry_id::pc_safety_cfg_assembly: return "Safety configuration assembly instance (0: none).";
    case entry_id::param_n: return "A configuration parameter: where it lives, its type, name, limits and default.";
    case entry_id::proxy_param_n: return "A parameter of the proxy (the adapter) standing for a module's parameter.";
    case entry_id::proxied_param_n: return "A parameter of a proxied device, reached through its proxy.";
    case entry_id::constructed_param_n: return "A parameter built from other parameters.";
    case entry_id::enum_n: return "Names of the values of ParamN with the same number (value, text pairs).";
    case entry_id::proxy_enum_n: return "Names of the values of ProxyParamN with the same number.";
    case entry_id::proxied_enum_n: return "Names of the values of ProxiedParamN with the same number.";
    case entry_id::enum_par_n: return "DeviceNet names of the values of ParamN, one string per value from 0.";
    case entry_id::group_n: return "A named group of parameters shown together by configuration tools.";
    case entry_id::assem_n: return "An assembly: a block of I/O or configuration data built from members.";
    case entry_id::assem_exa_n: return "An assembly whose size may come from a parameter.";
    case entry_id::proxy_assem_n: return "An assembly of the proxy standing for a module's assembly.";
    case entry_id::proxied_assem_n: return "An assembly of a proxied device.";
    case entry_id::proxy_assem_exa_n: return "A proxy assembly whose size may come from a parameter.";
    case entry_id::proxied_assem_exa_n: return "A proxied assembly whose size may come from a parameter.";
    case entry_id::variant_n: return "A member whose layout is chosen by a selector parameter.";
    case entry_id::variant_exa_n: return "A variant whose choices may be sized by parameters.";
    case entry_id::bitstring_variant_n: return "A member chosen by one bit of a selector.";
    case entry_id::array_n: return "An array of elements of one layout.";
    case entry_id::connection_n:
      return "An I/O connection a scanner may open: trigger and transport, parameters, RPI, sizes, formats, path.";
    case entry_id::proxy_connection_n:
      return "A connection of the proxy (the adapter) standing for a module's connection.";
    case entry_id::proxied_connection_n: return "A connection of a proxied device, opened through its proxy.";
    case entry_id::pitns: return "Whether the device supports Produced Inhibit Time in network format.";
    case entry_id::pitns_usec: return "Whether Produced Inhibit Time is given in microseconds.";
    case entry_id::safety_setting: return "A CIP Safety connection setting.";
    case entry_id::default_safety_connections: return "Safety connections opened by default (ConnectionN numbers).";
    case entry_id::port_n: return "A communication port: type, name, path to its port object, port number.";
    case entry_id::tspec_n: return "A traffic specification: direction, packet size and rate.";
    case entry_id::capacity_setting: return "A connection or packet-rate capacity of the device.";
    case entry_id::define_slots_in_rack: return "Number of slots in the rack.";
    case entry_id::slot_display_rule: return "Parameter that says how slots are shown.";
    case entry_id::width: return "Number of slots the module takes.";
    case entry_id::rack_n: return "A rack and the modules it may hold.";
    case entry_id::external_id:
      return "An identifier of the module as a hex byte string (e.g. \"85 02\"); its meaning is not documented.";
    case entry_id::object_setting: return "A class-level setting of this CIP object class.";
    case entry_id::attribute_list: return "Attributes the object class implements.";
    case entry_id::service_list: return "Services the object class implements.";
    case entry_id::service_description_n:
      return "A service of the object class: code, name, path, request and response.";
  }
  return "";
}

std::string_view summary_of(const schema::section_desc& s) {
  using schema::section_family;
  switch (s.family) {
    case section_family::file: return "About the EDS file itself: description, dates, revision.";
    case section_family::device: return "Identity of the device: vendor, type, product code, revision, names.";
    case section_family::classification: return "Networks and profiles the device belongs to.";
    case section_family::io_info: return "DeviceNet I/O: the connection types and their input and output data.";
    case section_family::variant_io_info: return "Alternative DeviceNet I/O layouts.";
    case section_family::param_class: return "Parameter Object class attributes.";
    case section_family::params: return "Configuration parameters (ParamN) and the names of their values (EnumN).";
    case section_family::enum_par: return "DeviceNet names of parameter values.";
    case section_family::groups: return "Named groups of parameters.";
    case section_family::assembly: return "Assembly Object: blocks of I/O and configuration data.";
    case section_family::connection_manager: return "Connection Manager: the I/O connections a scanner may open.";
    case section_family::port: return "Port Object: the device's communication ports.";
    case section_family::capacity: return "How many connections and packets per second the device handles.";
    case section_family::modular: return "Racks, slots and modules of a modular device.";
    case section_family::object_class: return "Class-level description of a CIP object class.";
    case section_family::unknown: break;
  }
  return "";
}

}  // namespace edsc::lsp
