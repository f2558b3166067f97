#pragma once
// EDS files of the wire tests (tests/sim, tests/eipscanner): shapes OpENer's
// sample EDS does not have.
namespace edsc::sim_test {

// Output data of 505 and 506 bytes (+ 2 + 4 = 511 and 512 on the wire),
// input data of 509 and 510 (+ 2 = 511 and 512), and 3000 bytes each way.
inline constexpr const char* bound_eds = R"eds([File]
DescText = "Large_Forward_Open bound";
CreateDate = 01-01-2026;
CreateTime = 00:00:00;
Revision = 1.0;

[Device]
VendCode = 65535;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 511;
MajRev = 1;
MinRev = 1;
ProdName = "bound of 511";

[Device Classification]
Class1 = EtherNetIP;

[Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","","",1000,1000000,20000,,,,,,,,,;

[Assembly]
Assem100 = "Input 509",,509,0x0000,,,;
Assem101 = "Input 510",,510,0x0000,,,;
Assem102 = "Input 3000",,3000,0x0000,,,;
Assem150 = "Output 505",,505,0x0000,,,;
Assem151 = "Config",,2,0x0000,,,;
Assem152 = "Output 506",,506,0x0000,,,;
Assem153 = "Output 3000",,3000,0x0000,,,;

[Connection Manager]
Connection1 = 0x84010002,0x44640405,Param1,,Assem150,Param1,,Assem100,,,,Assem151,"511 each way","","20 04 24 97 2C 96 2C 64";
Connection2 = 0x84010002,0x44640405,Param1,,Assem152,Param1,,Assem101,,,,Assem151,"512 each way","","20 04 24 97 2C 98 2C 65";
Connection3 = 0x84010002,0x44640405,Param1,,Assem153,Param1,,Assem102,,,,Assem151,"3000 bytes","","20 04 24 97 2C 99 2C 66";
)eds";

// Connection1 differs in every way between its two directions: O->T 8 data
// bytes (+ 2 sequence + 4 run/idle = 14) to Assem150 every 20 ms
// (Param1: 10 to 1000 ms), point-to-point only; T->O 24 data bytes (+ 2 =
// 26) from Assem100 every 50 ms (Param2: 40 to 1000 ms), multicast or
// point-to-point; configuration Assem151 of 4 bytes. A swap of anything
// between the directions is refused or shows in the data. Param3 and Param4
// are a scaled, settable INT and a read-only UDINT for the Parameter object.
inline constexpr const char* asym_eds = R"eds([File]
DescText = "two directions that differ";
CreateDate = 01-01-2026;
CreateTime = 00:00:00;
Revision = 1.3;

[Device]
VendCode = 65535;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 35;
MajRev = 1;
MinRev = 4;
ProdName = "asymmetric";

[Device Classification]
Class1 = EtherNetIP;

[Params]
Param1 = 0,,,0x0000,0xC8,4,"O->T RPI","us","",10000,1000000,20000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC8,4,"T->O RPI","us","",40000,1000000,50000,,,,,,,,,;
Param3 = 0,,,0x0004,0xC3,2,"Speed","rpm","motor speed",-1000,1000,250,2,3,4,5,,,,,1;
Param4 = 0,,,0x0010,0xC8,4,"Hours","h","run time",0,4000000000,7,,,,,,,,,;

[Assembly]
Assem100 = "Input",,24,0x0000,,,;
Assem150 = "Output",,8,0x0000,,,;
Assem151 = "Config",,4,0x0000,,,;

[Connection Manager]
Connection1 = 0x84010002,0x44640405,Param1,,Assem150,Param2,,Assem100,,,,Assem151,"Owner","","20 04 24 97 2C 96 2C 64";
)eds";

}  // namespace edsc::sim_test
