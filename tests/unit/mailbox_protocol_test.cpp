// One name for the mailbox protocols in every layer: element names, SII bits, InitCmd order.

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "esi/model/mailbox.hpp"

namespace {

using esi::MailboxProtocol;

TEST(MailboxProtocol, NamesAndSiiBitsFollowEtg1000Table18) {
    const std::pair<MailboxProtocol, std::uint16_t> bits[] = {{MailboxProtocol::aoe, 0x01}, {MailboxProtocol::eoe, 0x02},
                                                             {MailboxProtocol::coe, 0x04}, {MailboxProtocol::foe, 0x08},
                                                             {MailboxProtocol::soe, 0x10}, {MailboxProtocol::voe, 0x20}};
    for (const auto& [protocol, bit] : bits) EXPECT_EQ(esi::sii_bit(protocol), bit) << esi::to_string(protocol);
    EXPECT_EQ(esi::to_string(MailboxProtocol::coe), "CoE");
    EXPECT_EQ(esi::to_string(MailboxProtocol::voe), "VoE");
    EXPECT_EQ(esi::mailbox_protocol_names(0x3F, "none"), "AoE EoE CoE FoE SoE VoE");
    EXPECT_EQ(esi::mailbox_protocol_names(0x0C, "none"), "CoE FoE");
    EXPECT_EQ(esi::mailbox_protocol_names(0, "none"), "none");
}

TEST(MailboxProtocol, MailboxKnowsWhichItHas) {
    esi::Mailbox m;
    m.coe.emplace();
    m.foe.emplace();
    EXPECT_TRUE(m.has(MailboxProtocol::coe));
    EXPECT_TRUE(m.has(MailboxProtocol::foe));
    EXPECT_FALSE(m.has(MailboxProtocol::eoe));
    EXPECT_EQ(m.protocol_bits(), 0x04 | 0x08);
    EXPECT_NE(m.init_cmds(MailboxProtocol::coe), nullptr);
    EXPECT_EQ(m.init_cmds(MailboxProtocol::foe), nullptr);  // FoE carries no InitCmds
    EXPECT_EQ(m.init_cmds(MailboxProtocol::eoe), nullptr);  // absent
}

TEST(MailboxProtocol, InitCmdsAreVisitedCoeSoeEoeAoeEachInDocumentOrder) {
    esi::Mailbox m;
    auto add = [](std::vector<esi::InitCmd>& cmds, std::string comment) { cmds.emplace_back().comment = std::move(comment); };
    add(m.aoe.emplace().init_cmds, "aoe");
    add(m.eoe.emplace().init_cmds, "eoe");
    add(m.soe.emplace().init_cmds, "soe");
    add(m.coe.emplace().init_cmds, "coe 1");
    add(m.coe->init_cmds, "coe 2");
    std::vector<std::string> seen;
    m.for_each_init_cmd([&](MailboxProtocol protocol, const esi::InitCmd& cmd) {
        seen.push_back(std::string(esi::to_string(protocol)) + ":" + *cmd.comment);
    });
    EXPECT_EQ(seen, (std::vector<std::string>{"CoE:coe 1", "CoE:coe 2", "SoE:soe", "EoE:eoe", "AoE:aoe"}));
}

}  // namespace
