#include "net/hostile_esi.hpp"

namespace esi::test {

std::string HostileDevice::xml() const {
    const std::string mailbox_sms = coe ? "<Sm StartAddress=\"#x1800\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>\n"
                                          "<Sm StartAddress=\"#x1880\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>\n"
                                        : "";
    const std::string mailbox = coe ? "<Mailbox><CoE/></Mailbox>\n" : "";
    const std::string rx_sm = coe ? "2" : "0", tx_sm = coe ? "3" : "1";
    auto device = [&](const std::string& t, const std::string& product) {
        return "<Device Physics=\"YY\"><Type ProductCode=\"" + product + "\" RevisionNo=\"" + revision + "\">" + t + "</Type>\n" +
               "<Name><![CDATA[" + name + "]]></Name>\n"
               + mailbox_sms +
               "<Sm StartAddress=\"" + sm_start + "\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>\n"
               "<Sm StartAddress=\"#x1100\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>\n"
               "<Fmmu>Outputs</Fmmu><Fmmu>Inputs</Fmmu>\n"
               "<RxPdo Fixed=\"1\" Mandatory=\"1\" Sm=\"" + rx_sm + "\"><Index>#x1600</Index><Name>Outputs</Name>\n"
               "<Entry><Index>#x7000</Index><SubIndex>1</SubIndex><BitLen>" + rx_bit_len + "</BitLen><Name><![CDATA[" + entry_name +
               "]]></Name><DataType>USINT</DataType></Entry></RxPdo>\n"
               "<TxPdo Fixed=\"1\" Mandatory=\"1\" Sm=\"" + tx_sm + "\"><Index>#x1A00</Index><Name>Inputs</Name>\n"
               "<Entry><Index>#x6000</Index><SubIndex>1</SubIndex><BitLen>8</BitLen><Name>In</Name><DataType>USINT</DataType></Entry></TxPdo>\n"
               + mailbox + "</Device>\n";
    };
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo><Vendor><Id>" + vendor_id +
           "</Id><Name>Test</Name></Vendor><Descriptions><Groups/><Devices>\n" + device(type, product_code) +
           device(type + "-2", second_device_product_code) + "</Devices></Descriptions></EtherCATInfo>\n";
}

}  // namespace esi::test
