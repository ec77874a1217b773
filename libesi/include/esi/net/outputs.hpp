#pragma once
// The writers of esi-net: what each output kind is called, its files, and their text. Every
// writer reads the network model only and is a pure function of it (deterministic output).
//
//   eni   network.xml                  ETG.2100 EtherCAT Network Information
//   igh   igh_config.h, igh_config.c   IgH EtherLab master: ethercat cstruct-style tables,
//                                      domain registration, start-up SDOs and DC
//   lcec  lcec.xml                     linuxcnc-ethercat configuration (generic slaves)
//   map   process_image.json/.csv/.md  every process-image variable and where it sits
//   html  process_image.html           the same map drawn as bit-layout pictures: written by the
//                                      doc layer (esi/doc/process_image_page.hpp), which has the
//                                      page templates, so network_outputs leaves it to its caller
//   ros2  ros2/<slave>.yaml, ros2/ec_modules.ros2_control.xacro   ethercat_driver_ros2: written
//                                      by ros2_outputs (esi/net/ros2_config.hpp), which can refuse
//                                      a network, so network_outputs leaves it to its caller too

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "esi/io/atomic_write.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

enum class OutputKind { eni, igh, lcec, map, html, ros2 };

[[nodiscard]] std::span<const OutputKind> all_output_kinds();
[[nodiscard]] std::string_view to_string(OutputKind kind);
// "eni,igh,lcec,map,html,ros2" (any subset, any order); nullopt and a message when a name is unknown.
[[nodiscard]] std::optional<std::vector<OutputKind>> parse_output_kinds(std::string_view text, std::string& error);

[[nodiscard]] std::string write_eni(const Network& network);
[[nodiscard]] std::string write_igh_header(const Network& network);
[[nodiscard]] std::string write_igh_source(const Network& network);
[[nodiscard]] std::string write_lcec(const Network& network);
[[nodiscard]] std::string write_map_json(const Network& network);
[[nodiscard]] std::string write_map_csv(const Network& network);
[[nodiscard]] std::string write_map_markdown(const Network& network);

// The files of the chosen kinds under `directory`, in a fixed order, but for html and ros2 (see above);
// write them with write_files_atomically (all or nothing).
[[nodiscard]] std::vector<OutputFile> network_outputs(const Network& network, std::span<const OutputKind> kinds,
                                                      const std::filesystem::path& directory);

}  // namespace esi::net
