/* A small EtherCAT master on SOEM 2.x for the esi-sim tests (SOEM is GPL: built and run by the
 * tests only, never shipped). It scans the bus, maps the process data, brings every slave to OP,
 * runs cycles and prints one JSON object on stdout with what SOEM saw:
 *
 *   soem_master IFACE [--cycles N] [--echo] [--dc] [--sdo] [--scan-only]
 *
 * --echo   checks that each slave's inputs repeat its outputs of the cycle before (esi-sim --echo)
 * --dc     configures distributed clocks (ecx_configdc) before SAFEOP
 * --sdo    reads every object the slaves list over SDO Information, each sub-index by ecx_SDOread,
 *          in SAFEOP (before the process data has changed any object); prints the descriptions
 *          ecx_readODlist, ecx_readODdescription and ecx_readOE got ("od"). Only slaves whose SII
 *          declares SDO Information (CoE details bit 1): SOEM 2.x crashes on the mailbox error a
 *          slave without it answers (docs/esi-sim.md, "SOEM and SDO Information")
 * --init POS:INDEX:SUB:CA:HEX  an SDO download in PREOP->SAFEOP before the mapping is read (an ENI's
 *          CoE InitCmds for transition PS; POS is the slave's 0-based position, CA 1 for complete access)
 * --scan-only  stops after ecx_config_init (and reports the ESC's EEPROM and PDI state)
 * --state-timeout-ms T  how long to wait for SAFEOP, and for OP (default 4000)
 * --watchdog-ms W  sets each slave's process-data watchdog (0x0420, in 100 us ticks) before SAFEOP
 * --cycle-us U     waits U microseconds after each cycle (a paced cycle instead of back to back)
 * --stop-ms S      after the cycles, sends nothing for S ms, then reports what slave 1 shows
 *                  ("stopped": watchdog status 0x0440, expiry counter 0x0442, AL state and code, its
 *                  inputs after one more cycle) and whether it returns to OP once the master
 *                  cycles again and acknowledges the error
 */
#include "soem/soem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static ecx_contextt context;
static uint8 io_map[65536];

#define MAX_INIT_CMDS 256
static struct
{
   int position, index, sub, complete_access, size;
   uint8 data[512];
} init_cmds[MAX_INIT_CMDS];
static int init_cmd_count, init_cmd_failures;

static int parse_init(const char *text)
{
   if (init_cmd_count >= MAX_INIT_CMDS) return 0;
   char hex[1100] = {0};
   int position, index, sub, ca;
   if (sscanf(text, "%d:%i:%i:%d:%1099s", &position, &index, &sub, &ca, hex) != 5) return 0;
   int n = (int)strlen(hex) / 2;
   if (n > 512) return 0;
   for (int i = 0; i < n; ++i)
   {
      unsigned byte;
      sscanf(hex + 2 * i, "%2x", &byte);
      init_cmds[init_cmd_count].data[i] = (uint8)byte;
   }
   init_cmds[init_cmd_count].position = position;
   init_cmds[init_cmd_count].index = index;
   init_cmds[init_cmd_count].sub = sub;
   init_cmds[init_cmd_count].complete_access = ca;
   init_cmds[init_cmd_count].size = n;
   ++init_cmd_count;
   return 1;
}

/* SOEM calls this for each slave in PREOP, before it reads the slave's PDO mapping. */
static int apply_init_cmds(ecx_contextt *ctx, uint16 slave)
{
   for (int i = 0; i < init_cmd_count; ++i)
   {
      if (init_cmds[i].position != slave - 1) continue;
      int wkc = ecx_SDOwrite(ctx, slave, (uint16)init_cmds[i].index, (uint8)init_cmds[i].sub,
                             init_cmds[i].complete_access ? TRUE : FALSE, init_cmds[i].size, init_cmds[i].data, EC_TIMEOUTRXM);
      if (wkc <= 0) ++init_cmd_failures;
   }
   return 1;
}

static void print_string(const char *s)
{
   putchar('"');
   for (; *s; ++s)
   {
      unsigned char c = (unsigned char)*s;
      if (c == '"' || c == '\\') printf("\\%c", c);
      else if (c < 0x20) printf("\\u%04x", c);
      else putchar(c);
   }
   putchar('"');
}

static double now_ms(void)
{
   struct timespec t;
   clock_gettime(CLOCK_MONOTONIC, &t);
   return t.tv_sec * 1000.0 + t.tv_nsec / 1e6;
}

static uint8 pattern(int cycle, int slave, uint32 i) { return (uint8)(cycle * 7 + slave * 31 + i * 13 + 1); }

/* Writes the outputs of one cycle: every output byte of every slave gets a pattern. */
static void write_outputs(int cycle)
{
   for (int s = 1; s <= context.slavecount; ++s)
   {
      ec_slavet *slave = &context.slavelist[s];
      uint32 bytes = slave->Obytes ? slave->Obytes : (slave->Obits ? 1 : 0);
      for (uint32 i = 0; i < bytes && slave->outputs; ++i) slave->outputs[i] = pattern(cycle, s, i);
   }
}

/* Whether each slave's inputs hold the outputs written in `cycle` where both exist (whole bytes). */
static int echo_matches(int cycle)
{
   int all = 1;
   for (int s = 1; s <= context.slavecount; ++s)
   {
      ec_slavet *slave = &context.slavelist[s];
      uint32 n = slave->Obytes < slave->Ibytes ? slave->Obytes : slave->Ibytes;
      for (uint32 i = 0; i < n; ++i)
         if (slave->inputs[i] != pattern(cycle, s, i)) all = 0;
   }
   return all;
}

static void print_slaves(void)
{
   printf(",\"slave\":[");
   for (int s = 1; s <= context.slavecount; ++s)
   {
      ec_slavet *slave = &context.slavelist[s];
      uint16 eeprom_status = 0, dl_status = 0;
      ecx_FPRD(&context.port, slave->configadr, ECT_REG_EEPSTAT, sizeof eeprom_status, &eeprom_status, EC_TIMEOUTRET3);
      ecx_FPRD(&context.port, slave->configadr, ECT_REG_DLSTAT, sizeof dl_status, &dl_status, EC_TIMEOUTRET3);
      printf("%s{\"position\":%d,\"name\":", s > 1 ? "," : "", s - 1);
      print_string(slave->name);
      printf(",\"vendor\":%u,\"product\":%u,\"revision\":%u,\"configadr\":%u", slave->eep_man, slave->eep_id, slave->eep_rev,
             slave->configadr);
      printf(",\"obits\":%u,\"ibits\":%u,\"state\":%u,\"al_status_code\":%u,\"al_status_text\":", slave->Obits, slave->Ibits,
             slave->state, slave->ALstatuscode);
      print_string(ec_ALstatuscode2string(slave->ALstatuscode));
      printf(",\"eeprom_status\":%u,\"eeprom_checksum_error\":%s,\"eeprom_not_loaded\":%s,\"dl_status\":%u,"
             "\"pdi_operational\":%s,\"has_dc\":%s,\"mbx_protocols\":%u,\"coe_details\":%u}",
             eeprom_status, (eeprom_status & 0x0800) ? "true" : "false", (eeprom_status & 0x1000) ? "true" : "false",
             dl_status, (dl_status & 1) ? "true" : "false", slave->hasdc ? "true" : "false", slave->mbx_proto,
             slave->CoEdetails);
   }
   printf("]");
}

static void print_hex(const uint8 *data, int size)
{
   putchar('"');
   for (int i = 0; i < size; ++i) printf("%02x", data[i]);
   putchar('"');
}

static void read_dictionaries(void)
{
   static ec_ODlistt od;
   static ec_OElistt oe;
   static uint8 value[4096];
   /* What SDO Information described, printed after the reads (one array per key). */
   static char descriptions[1 << 20];
   size_t used = 0;
   printf(",\"sdo\":[");
   int first = 1;
   for (int s = 1; s <= context.slavecount; ++s)
   {
      if (!(context.slavelist[s].mbx_proto & ECT_MBXPROT_COE)) continue;
      if (!(context.slavelist[s].CoEdetails & ECT_COEDET_SDOINFO)) continue;
      memset(&od, 0, sizeof od);
      if (ecx_readODlist(&context, (uint16)s, &od) <= 0) continue;
      for (int i = 0; i < od.Entries; ++i)
      {
         ecx_readODdescription(&context, (uint16)i, &od);
         memset(&oe, 0, sizeof oe);
         ecx_readOE(&context, (uint16)i, &od, &oe);
         used += (size_t)snprintf(descriptions + used, sizeof descriptions - used,
                                  "%s{\"slave\":%d,\"index\":%u,\"data_type\":%u,\"object_code\":%u,\"max_sub\":%u,\"entries\":[",
                                  used ? "," : "", s - 1, od.Index[i], od.DataType[i], od.ObjectCode[i], od.MaxSub[i]);
         for (int sub = 0; sub <= od.MaxSub[i] && sub < EC_MAXOELIST && used < sizeof descriptions; ++sub)
            used += (size_t)snprintf(descriptions + used, sizeof descriptions - used,
                                     "%s{\"sub\":%d,\"data_type\":%u,\"bit_length\":%u,\"access\":%u}", sub ? "," : "", sub,
                                     oe.DataType[sub], oe.BitLength[sub], oe.ObjAccess[sub]);
         if (used < sizeof descriptions) used += (size_t)snprintf(descriptions + used, sizeof descriptions - used, "]}");
         if (used >= sizeof descriptions) used = sizeof descriptions - 1;
         for (int sub = 0; sub <= od.MaxSub[i] && sub < EC_MAXOELIST; ++sub)
         {
            if (sub > 0 && oe.DataType[sub] == 0 && oe.BitLength[sub] == 0) continue;
            int size = sizeof value;
            memset(value, 0, sizeof value);
            int wkc = ecx_SDOread(&context, (uint16)s, od.Index[i], (uint8)sub, FALSE, &size, value, EC_TIMEOUTRXM);
            printf("%s{\"slave\":%d,\"index\":%u,\"sub\":%d,\"ok\":%s,\"value\":", first ? "" : ",", s - 1, od.Index[i], sub,
                   wkc > 0 ? "true" : "false");
            print_hex(value, wkc > 0 ? size : 0);
            printf("}");
            first = 0;
         }
      }
      while (ecx_iserror(&context))
      {
         ec_errort error;
         ecx_poperror(&context, &error);
      }
   }
   printf("],\"od\":[%s]", descriptions);
}

/* The master stops cycling for stop_ms: what slave 1 shows then, and whether it comes back to OP
 * once the master cycles again and acknowledges the error. */
static void report_stop(int stop_ms, int cycle, int state_timeout_ms)
{
   ec_slavet *slave = &context.slavelist[1];
   uint16 status = 0xFFFF, code = 0xFFFF, al = 0;
   uint8 counter = 0xFF, counter_before = 0xFF;
   uint16 al_before = 0;
   /* Still cycling until here: nothing has expired, the slave is in OP. */
   ecx_FPRD(&context.port, slave->configadr, ECT_REG_WDCNT, sizeof counter_before, &counter_before, EC_TIMEOUTRET3);
   ecx_FPRD(&context.port, slave->configadr, ECT_REG_ALSTAT, sizeof al_before, &al_before, EC_TIMEOUTRET3);
   osal_usleep((uint32)stop_ms * 1000);
   /* The first frame after the silence: the ESC finds the watchdog expired before this read. */
   ecx_FPRD(&context.port, slave->configadr, 0x0440, sizeof status, &status, EC_TIMEOUTRET3);
   ecx_FPRD(&context.port, slave->configadr, ECT_REG_WDCNT, sizeof counter, &counter, EC_TIMEOUTRET3);
   ecx_FPRD(&context.port, slave->configadr, ECT_REG_ALSTAT, sizeof al, &al, EC_TIMEOUTRET3);
   ecx_FPRD(&context.port, slave->configadr, ECT_REG_ALSTATCODE, sizeof code, &code, EC_TIMEOUTRET3);
   /* One more cycle: the inputs the slave wrote after it found the watchdog expired. */
   write_outputs(cycle);
   ecx_send_processdata(&context);
   ecx_receive_processdata(&context, 100000);
   int inputs_zero = 1;
   for (uint32 i = 0; i < slave->Ibytes; ++i)
      if (slave->inputs[i]) inputs_zero = 0;
   /* Back to OP: cycle, acknowledge the error, request OP. */
   slave->state = EC_STATE_OPERATIONAL | EC_STATE_ACK;
   ecx_writestate(&context, 1);
   int op = 0;
   for (int i = 0; i < state_timeout_ms / 10 && !op; ++i)
   {
      write_outputs(cycle + 1 + i);
      ecx_send_processdata(&context);
      ecx_receive_processdata(&context, 100000);
      op = ecx_statecheck(&context, 1, EC_STATE_OPERATIONAL, 10000) == EC_STATE_OPERATIONAL;
   }
   printf(",\"stopped\":{\"watchdog_counter_before\":%u,\"al_status_before\":%u,\"watchdog_status\":%u,\"watchdog_counter\":%u,\"al_status\":%u,\"al_status_code\":%u,"
          "\"inputs_zero\":%s,\"back_in_op\":%s}",
          counter_before, etohs(al_before), etohs(status), counter, etohs(al), etohs(code), inputs_zero ? "true" : "false", op ? "true" : "false");
}

int main(int argc, char **argv)
{
   if (argc < 2)
   {
      fprintf(stderr, "usage: soem_master IFACE [--cycles N] [--echo] [--dc] [--sdo] [--scan-only] [--state-timeout-ms T]\n");
      return 2;
   }
   int cycles = 1000, echo = 0, dc = 0, sdo = 0, scan_only = 0, state_timeout_ms = 4000;
   int watchdog_ms = 0, cycle_us = 0, stop_ms = 0;
   for (int i = 2; i < argc; ++i)
   {
      if (!strcmp(argv[i], "--cycles") && i + 1 < argc) cycles = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--echo")) echo = 1;
      else if (!strcmp(argv[i], "--dc")) dc = 1;
      else if (!strcmp(argv[i], "--sdo")) sdo = 1;
      else if (!strcmp(argv[i], "--scan-only")) scan_only = 1;
      else if (!strcmp(argv[i], "--init") && i + 1 < argc)
      {
         if (!parse_init(argv[++i]))
         {
            fprintf(stderr, "soem_master: bad --init %s\n", argv[i]);
            return 2;
         }
      }
      else if (!strcmp(argv[i], "--state-timeout-ms") && i + 1 < argc) state_timeout_ms = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--watchdog-ms") && i + 1 < argc) watchdog_ms = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--cycle-us") && i + 1 < argc) cycle_us = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--stop-ms") && i + 1 < argc) stop_ms = atoi(argv[++i]);
   }
   const double start = now_ms();
   if (!ecx_init(&context, argv[1]))
   {
      printf("{\"init\":false}\n");
      return 1;
   }
   int found = ecx_config_init(&context);
   printf("{\"init\":true,\"slaves\":%d", found > 0 ? context.slavecount : 0);
   if (found <= 0 || scan_only)
   {
      ecx_readstate(&context);
      print_slaves();
      printf("}\n");
      ecx_close(&context);
      return 0;
   }
   for (int s = 1; s <= context.slavecount; ++s) context.slavelist[s].PO2SOconfig = apply_init_cmds;
   /* In PREOP, before any process data has changed an object. */
   ecx_config_map_group(&context, io_map, 0);
   if (dc) ecx_configdc(&context);
   if (watchdog_ms > 0)
      for (int s = 1; s <= context.slavecount; ++s)
      {
         uint16 ticks = htoes((uint16)(watchdog_ms * 10)); /* the default divider: 100 us per tick */
         ecx_FPWR(&context.port, context.slavelist[s].configadr, 0x0420, sizeof ticks, &ticks, EC_TIMEOUTRET3);
      }
   ec_groupt *group = &context.grouplist[0];
   int expected_wkc = group->outputsWKC * 2 + group->inputsWKC;
   ecx_statecheck(&context, 0, EC_STATE_SAFE_OP, state_timeout_ms * 1000);
   /* In SAFEOP, before the first outputs: no object has changed yet. */
   if (sdo) read_dictionaries();
   write_outputs(0);
   ecx_send_processdata(&context);
   ecx_receive_processdata(&context, EC_TIMEOUTRET);
   context.slavelist[0].state = EC_STATE_OPERATIONAL;
   ecx_writestate(&context, 0);
   int op = 0;
   for (int i = 0; i < state_timeout_ms / 50 && !op; ++i)
   {
      ecx_send_processdata(&context);
      ecx_receive_processdata(&context, EC_TIMEOUTRET);
      op = ecx_statecheck(&context, 0, EC_STATE_OPERATIONAL, 50000) == EC_STATE_OPERATIONAL;
   }
   const double to_op = now_ms() - start;
   int wkc_ok = 0, echo_ok = 0, echo_checked = 0, ran = 0;
   if (op)
   {
      for (int c = 1; c <= cycles; ++c)
      {
         write_outputs(c);
         ecx_send_processdata(&context);
         /* A generous timeout: the tests run on loaded machines, and a late frame is not the
          * emulator's fault; a wrong working counter is. */
         int wkc = ecx_receive_processdata(&context, 100000);
         ++ran;
         if (wkc == expected_wkc) ++wkc_ok;
         if (cycle_us > 0) osal_usleep((uint32)cycle_us);
         /* The inputs read in cycle c were written by the slave after cycle c - 1's outputs. */
         if (echo && c > 2)
         {
            ++echo_checked;
            echo_ok += echo_matches(c - 1);
         }
      }
   }
   if (op && stop_ms > 0) report_stop(stop_ms, cycles + 1, state_timeout_ms);
   ecx_readstate(&context);
   printf(",\"expected_wkc\":%d,\"op\":%s,\"to_op_ms\":%.1f,\"cycles\":%d,\"wkc_ok\":%d,\"echo_checked\":%d,\"echo_ok\":%d",
          expected_wkc, op ? "true" : "false", to_op, ran, wkc_ok, echo_checked, echo_ok);
   printf(",\"obytes\":%u,\"ibytes\":%u,\"init_cmds\":%d,\"init_cmd_failures\":%d", group->Obytes, group->Ibytes,
          init_cmd_count, init_cmd_failures);
   print_slaves();
   printf("}\n");
   context.slavelist[0].state = EC_STATE_INIT;
   ecx_writestate(&context, 0);
   ecx_close(&context);
   return 0;
}
