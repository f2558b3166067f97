#pragma once
// Internal: the schema rows, split over two files by section family.
#include "schema/cip_types.hpp"
#include "schema/schema.hpp"

namespace edsc::schema::tables {

extern const keyword_desc file_keywords[9];
extern const keyword_desc device_keywords[12];
extern const keyword_desc classification_keywords[1];
extern const keyword_desc io_info_keywords[9];
extern const keyword_desc param_class_keywords[4];
extern const keyword_desc params_keywords[7];
extern const keyword_desc enum_par_keywords[1];
extern const keyword_desc groups_keywords[1];

extern const keyword_desc assembly_keywords[10];
extern const keyword_desc connection_manager_keywords[11];
extern const keyword_desc port_keywords[1];
extern const keyword_desc capacity_keywords[12];
extern const keyword_desc modular_keywords[5];
extern const keyword_desc common_keywords[10];
extern const keyword_desc tcpip_keywords[2];
extern const keyword_desc ethernet_link_keywords[3];
extern const keyword_desc dlr_keywords[2];
extern const keyword_desc ingress_egress_keywords[1];
extern const keyword_desc service_description_keyword[1];

}  // namespace edsc::schema::tables
