/* The EtherCAT master of the SOES tests (tests/sim_soes), on SOEM 2.x (GPL: built and run by the
 * tests only, never shipped). It scans the bus, optionally rewrites PDO objects over CoE in PREOP,
 * maps the process data with ecx_config_map_group (outputs then inputs, each slave's data at the
 * offsets esi-net's process_image.json states), brings the slaves to OP, runs cycles, reads back
 * the PDO assignment and mapping over CoE and prints one JSON object on stdout:
 *
 *   soes_master IFACE [--cycles N] [--state-timeout-ms T] [--sdo-write SLAVE:INDEX:SUB:BYTES:VALUE]...
 *               [--overlap] [--dc-sync0 SLAVE:CYCLE_NS]...
 *
 * --overlap    maps in overlapped mode (ecx_contextt.overlappedMode, SOEM's internal
 *              ecx_config_overlap_map_group): each slave's inputs and outputs share their logical
 *              start, as in esi-net's ENI and process_image.json.
 * --dc-sync0   configures distributed clocks (ecx_configdc) and activates SYNC0 on the slave
 *              (ecx_dcsync0), what eniconv's table does not carry from the ENI.
 * --sdo-write  an expedited SDO download in PREOP (SOEM's PO2SOconfig hook, before the mapping is
 *              read; hex numbers, SLAVE is the 1-based SOEM position); the abort code of each is reported.
 * When built with ESI_ENI_TABLE the ENI start-up table eniconv wrote is applied (context.ENI).
 */
#include "soem/soem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef ESI_ENI_TABLE
extern ec_enit ESI_ENI_TABLE;
#endif

static ecx_contextt context;
static uint8 io_map[65536];

struct sdo_write
{
   uint16 slave, index;
   uint8 sub, bytes;
   uint32 value;
   int done;
   uint32 abort_code;
};
static struct sdo_write writes[256];
static int nwrites;

static uint8 pattern(int cycle, uint32 i) { return (uint8)(cycle * 7 + i * 13 + 1); }

static void print_hex(const uint8 *data, uint32 size)
{
   putchar('"');
   for (uint32 i = 0; i < size; ++i) printf("%02x", data[i]);
   putchar('"');
}

/* The SDO abort code of the last failed transfer, or 0x100 + SOEM's error type for failures
 * other than an abort (mailbox error, unexpected frame). */
static uint32 last_abort(void)
{
   uint32 code = 0;
   while (ecx_iserror(&context))
   {
      ec_errort error;
      if (!ecx_poperror(&context, &error)) break;
      code = error.Etype == EC_ERR_TYPE_SDO_ERROR ? (uint32)error.AbortCode : 0x100u + (uint32)error.Etype;
   }
   return code;
}

static int read_u32(uint16 slave, uint16 index, uint8 sub, uint32 *value)
{
   int size = sizeof *value;
   *value = 0;
   return ecx_SDOread(&context, slave, index, sub, FALSE, &size, value, EC_TIMEOUTRXM) > 0;
}

/* 0x1C12/0x1C13 and every PDO they assign, as the slave answers over CoE. */
static void print_pdo_assignment(uint16 slave)
{
   printf(",\"assign\":{");
   for (uint16 sm_index = 0x1C12; sm_index <= 0x1C13; ++sm_index)
   {
      uint8 count = 0;
      int size = 1;
      int ok = ecx_SDOread(&context, slave, sm_index, 0, FALSE, &size, &count, EC_TIMEOUTRXM) > 0;
      printf("%s\"%u\":[", sm_index == 0x1C12 ? "" : ",", sm_index);
      for (uint8 i = 1; ok && i <= count; ++i)
      {
         uint16 pdo = 0;
         size = 2;
         if (ecx_SDOread(&context, slave, sm_index, i, FALSE, &size, &pdo, EC_TIMEOUTRXM) <= 0) break;
         uint8 entries = 0;
         size = 1;
         ecx_SDOread(&context, slave, pdo, 0, FALSE, &size, &entries, EC_TIMEOUTRXM);
         printf("%s{\"pdo\":%u,\"entries\":[", i > 1 ? "," : "", pdo);
         for (uint8 e = 1; e <= entries; ++e)
         {
            uint32 entry = 0;
            read_u32(slave, pdo, e, &entry);
            printf("%s%u", e > 1 ? "," : "", entry);
         }
         printf("]}");
      }
      printf("]");
   }
   printf("}");
   last_abort();
}

/* PREOP to SAFEOP, before ecx_config_map_group reads the mapping over CoE: where SOEM users
 * configure a slave (the ENI's PS commands run just before). */
static int write_sdos(ecx_contextt *ctx, uint16 slave)
{
   for (int i = 0; i < nwrites; ++i)
   {
      if (writes[i].slave != slave) continue;
      uint32 value = writes[i].value;
      int wkc = ecx_SDOwrite(ctx, slave, writes[i].index, writes[i].sub, FALSE, writes[i].bytes, &value, EC_TIMEOUTRXM);
      writes[i].abort_code = last_abort();
      writes[i].done = wkc > 0;
   }
   return 0;
}

struct dc_sync
{
   uint16 slave;
   uint32 cycle_ns;
};

int main(int argc, char **argv)
{
   static struct dc_sync syncs[64];
   int nsyncs = 0, overlap = 0;
   if (argc < 2)
   {
      fprintf(stderr, "usage: soes_master IFACE [--cycles N] [--state-timeout-ms T] [--sdo-write S:I:SUB:BYTES:VALUE]...\n");
      return 2;
   }
   int cycles = 1000, state_timeout_ms = 4000;
   for (int i = 2; i < argc; ++i)
   {
      if (!strcmp(argv[i], "--cycles") && i + 1 < argc) cycles = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--state-timeout-ms") && i + 1 < argc) state_timeout_ms = atoi(argv[++i]);
      else if (!strcmp(argv[i], "--sdo-write") && i + 1 < argc && nwrites < 256)
      {
         unsigned s, index, sub, bytes, value;
         if (sscanf(argv[++i], "%x:%x:%x:%x:%x", &s, &index, &sub, &bytes, &value) != 5) return 2;
         writes[nwrites++] = (struct sdo_write){(uint16)s, (uint16)index, (uint8)sub, (uint8)bytes, value, 0, 0};
      }
      else if (!strcmp(argv[i], "--overlap")) overlap = 1;
      else if (!strcmp(argv[i], "--dc-sync0") && i + 1 < argc && nsyncs < 64)
      {
         unsigned s, cycle;
         if (sscanf(argv[++i], "%u:%u", &s, &cycle) != 2) return 2;
         syncs[nsyncs++] = (struct dc_sync){(uint16)s, cycle};
      }
      else return 2;
   }
   if (!ecx_init(&context, argv[1]))
   {
      printf("{\"init\":false}\n");
      return 1;
   }
#ifdef ESI_ENI_TABLE
   context.ENI = &ESI_ENI_TABLE;
#endif
   int found = ecx_config_init(&context);
   printf("{\"init\":true,\"slaves\":%d", found > 0 ? context.slavecount : 0);
   if (found <= 0)
   {
      printf("}\n");
      ecx_close(&context);
      return 0;
   }
   for (int s = 1; s <= context.slavecount; ++s) context.slavelist[s].PO2SOconfig = write_sdos;
   /* SOEM 2.x keeps ecx_config_overlap_map_group internal: ecx_config_map_group takes it when
    * the context is in overlapped mode. */
   context.overlappedMode = overlap ? TRUE : FALSE;
   ecx_config_map_group(&context, io_map, 0);
   if (nsyncs > 0) ecx_configdc(&context);
   for (int i = 0; i < nsyncs; ++i) ecx_dcsync0(&context, syncs[i].slave, TRUE, syncs[i].cycle_ns, 0);
   printf(",\"sdo_writes\":[");
   for (int i = 0; i < nwrites; ++i)
      printf("%s{\"index\":%u,\"sub\":%u,\"ok\":%s,\"abort\":%u}", i ? "," : "", writes[i].index, writes[i].sub,
             writes[i].done && !writes[i].abort_code ? "true" : "false", writes[i].abort_code);
   printf("]");
   ec_groupt *group = &context.grouplist[0];
   int expected_wkc = group->outputsWKC * 2 + group->inputsWKC;
   ecx_statecheck(&context, 0, EC_STATE_SAFE_OP, state_timeout_ms * 1000);
   for (uint32 i = 0; i < group->Obytes; ++i) io_map[i] = pattern(0, i);
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
   int wkc_ok = 0, ran = 0;
   for (int c = 1; op && c <= cycles; ++c)
   {
      for (uint32 i = 0; i < group->Obytes; ++i) io_map[i] = pattern(c, i);
      ecx_send_processdata(&context);
      /* A generous timeout: a late frame on a loaded machine is not the slave's fault. */
      if (ecx_receive_processdata(&context, 100000) == expected_wkc) ++wkc_ok;
      ++ran;
   }
   /* The inputs of one more exchange with the same outputs: by then the firmware has answered
    * the last outputs and its inputs are settled. */
   if (op)
   {
      ecx_send_processdata(&context);
      ecx_receive_processdata(&context, 100000);
   }
   ecx_readstate(&context);
   printf(",\"expected_wkc\":%d,\"op\":%s,\"cycles\":%d,\"wkc_ok\":%d,\"obytes\":%u,\"ibytes\":%u", expected_wkc,
          op ? "true" : "false", ran, wkc_ok, group->Obytes, group->Ibytes);
   printf(",\"outputs\":");
   print_hex(io_map, group->Obytes);
   printf(",\"inputs\":");
   print_hex(io_map + group->Obytes, group->Ibytes);
   printf(",\"slave\":[");
   for (int s = 1; s <= context.slavecount; ++s)
   {
      ec_slavet *slave = &context.slavelist[s];
      printf("%s{\"name\":\"%s\",\"state\":%u,\"al_status_code\":%u,\"obits\":%u,\"ibits\":%u", s > 1 ? "," : "", slave->name,
             slave->state, slave->ALstatuscode, slave->Obits, slave->Ibits);
      printf(",\"output_offset\":%ld,\"output_bit\":%u,\"input_offset\":%ld,\"input_bit\":%u",
             slave->outputs ? (long)(slave->outputs - io_map) : -1L, slave->Ostartbit,
             slave->inputs ? (long)(slave->inputs - io_map - group->Obytes) : -1L, slave->Istartbit);
      if (slave->mbx_proto & ECT_MBXPROT_COE) print_pdo_assignment((uint16)s);
      printf("}");
   }
   printf("]}\n");
   context.slavelist[0].state = EC_STATE_INIT;
   ecx_writestate(&context, 0);
   ecx_close(&context);
   return 0;
}
