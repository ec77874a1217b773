/*
 * SOES's own PDO remapping against the tables generated from samples/inverter-stoeber-mds5000.yaml
 * (flexible mapping: 0x1600-0x1603 and 0x1A00-0x1A03 with six entries each, 0x1C12/0x1C13
 * writable). Built with AddressSanitizer by tests/codegen/soes_stack_test.cpp: SOES copies the
 * SM2/SM3 bytes into its static rxpdo/txpdo buffers, so a buffer sized for less than the mapping
 * ends the program with an ASan report. Each scenario remaps over SDO in PreOp, goes to Op and
 * runs a process-data cycle; the program prints every check that fails and exits 1.
 */
#include <stdio.h>
#include <string.h>

#include "ecat_slv.h"
#include "esc_sim.h"
#include "utypes.h"

_Objects Obj;

void cb_get_inputs (void) {}
void cb_set_outputs (void) {}

/* Parameters of the STÖBER sample: A180 (USINT), D230 and C230 (INT), E200 (USINT) ... */
#define A180 0x20B4u
#define D230 0x26E6u
#define C230 0x24E6u
#define MAP(index, subindex, bits) (((uint32_t)(index) << 16) | ((uint32_t)(subindex) << 8) | (bits))
#define GAP(bits) MAP (0, 0, bits)

static int failures;

static void check (int ok, const char * what)
{
   if (!ok)
   {
      printf ("FAILED: %s\n", what);
      failures++;
   }
}

static void download (uint16_t index, uint8_t subindex, uint32_t value, uint8_t size)
{
   char what[96];
   const uint32_t abort_code = esc_sim_sdo_download (index, subindex, value, size);
   snprintf (what, sizeof what, "SDO download 0x%04X:%02X = 0x%X (abort 0x%08X)", index, subindex, value, abort_code);
   check (abort_code == 0, what);
}

static uint32_t upload (uint16_t index, uint8_t subindex)
{
   uint32_t value = 0;
   char what[64];
   snprintf (what, sizeof what, "SDO upload 0x%04X:%02X", index, subindex);
   check (esc_sim_sdo_upload (index, subindex, &value) == 0, what);
   return value;
}

/* Writes a mapping object the way a master does: count 0, the entries, the count. */
static void map (uint16_t pdo, const uint32_t * entries, uint8_t count)
{
   uint8_t i;
   download (pdo, 0, 0, 1);
   for (i = 0; i < count; i++) download (pdo, (uint8_t)(i + 1), entries[i], 4);
   download (pdo, 0, count, 1);
}

static void assign (uint16_t assignment, const uint16_t * pdos, uint8_t count)
{
   uint8_t i;
   download (assignment, 0, 0, 1);
   for (i = 0; i < count; i++) download (assignment, (uint8_t)(i + 1), pdos[i], 2);
   download (assignment, 0, count, 1);
}

/* PreOp -> SafeOp -> Op with SM2/SM3 set to the expected sizes. */
static int go_op (uint16_t sm2_bytes, uint16_t sm3_bytes, const char * scenario)
{
   char what[128];
   uint8_t state;
   esc_sim_configure_pdo_sm (2, sm2_bytes);
   esc_sim_configure_pdo_sm (3, sm3_bytes);
   state = esc_sim_request_state (ESCsafeop);
   snprintf (what, sizeof what, "%s: SafeOp accepted (AL status 0x%02X, SOES computed SM2 %u, SM3 %u bytes)", scenario, state,
             ESCvar.ESC_SM2_sml, ESCvar.ESC_SM3_sml);
   check (state == ESCsafeop, what);
   if (state != ESCsafeop) return 0;
   state = esc_sim_request_state (ESCop);
   snprintf (what, sizeof what, "%s: Op accepted (AL status 0x%02X)", scenario, state);
   check (state == ESCop, what);
   return state == ESCop;
}

static void back_to_preop (void)
{
   check (esc_sim_request_state (ESCpreop) == ESCpreop, "back to PreOp");
}

int main (void)
{
   static esc_cfg_t config;
   uint8_t out[64], in[64];
   const uint16_t tx_default[] = {0x1A00, 0x1A01};
   const uint16_t tx_default_bytes = 7; /* E200, D200, E100, E02 */

   esc_sim_reset ();
   ecat_slv_init (&config);
   check (esc_sim_request_state (ESCpreop) == ESCpreop, "PreOp");

   /* 1. Assign 0x1601 alone, with one entry. */
   {
      const uint32_t entries[] = {MAP (A180, 0, 8)};
      const uint16_t pdos[] = {0x1601};
      map (0x1601, entries, 1);
      assign (0x1C12, pdos, 1);
      if (go_op (1, tx_default_bytes, "0x1601 with one entry"))
      {
         memset (out, 0, sizeof out);
         out[0] = 0x5A;
         esc_sim_cycle (out, 1, in, tx_default_bytes);
         check (upload (A180, 0) == 0x5A, "0x1601: A180 receives the output byte");
         /* Mapping and assignment are PreOp-only: SafeOp and Op refuse a change. */
         check (esc_sim_sdo_download (0x1C12, 0, 0, 1) == 0x08000022, "0x1C12 refuses a write in Op");
         check (esc_sim_sdo_download (0x1601, 0, 0, 1) == 0x08000022, "0x1601 refuses a write in Op");
      }
      back_to_preop ();
   }

   /* 2. A mapping with a padding entry: A180, an 8-bit gap, D230. */
   {
      const uint32_t entries[] = {MAP (A180, 0, 8), GAP (8), MAP (D230, 0, 16)};
      const uint16_t pdos[] = {0x1600};
      map (0x1600, entries, 3);
      assign (0x1C12, pdos, 1);
      if (go_op (4, tx_default_bytes, "0x1600 with a padding entry"))
      {
         memset (out, 0, sizeof out);
         out[0] = 0x11;
         out[1] = 0xEE; /* the gap */
         out[2] = 0x34;
         out[3] = 0x12;
         esc_sim_cycle (out, 4, in, tx_default_bytes);
         check (upload (A180, 0) == 0x11, "padding: A180 before the gap");
         check (upload (D230, 0) == 0x1234, "padding: D230 after the gap");
      }
      back_to_preop ();
   }

   /* 3. More than the default maps: two PDOs of six entries each (12 mappings, 22 bytes). */
   {
      const uint32_t first[] = {MAP (A180, 0, 8), GAP (8), MAP (D230, 0, 16), MAP (C230, 0, 16), GAP (16), GAP (16)};
      const uint32_t second[] = {GAP (16), GAP (16), GAP (16), GAP (16), GAP (16), MAP (D230, 0, 16)};
      const uint16_t pdos[] = {0x1600, 0x1601};
      map (0x1600, first, 6);
      map (0x1601, second, 6);
      assign (0x1C12, pdos, 2);
      if (go_op (22, tx_default_bytes, "two full RxPDOs"))
      {
         memset (out, 0, sizeof out);
         out[20] = 0x78;
         out[21] = 0x56;
         esc_sim_cycle (out, 22, in, tx_default_bytes);
         check (upload (D230, 0) == 0x5678, "two full RxPDOs: D230 from the last entry");
      }
      back_to_preop ();
   }

   /* 4. Inputs remapped past the default: 0x1A00 as it is and 0x1A01 with six 16-bit entries. */
   {
      const uint32_t entries[] = {MAP (0x26C8, 0, 16), GAP (16), GAP (16), GAP (16), GAP (16), MAP (0x2864, 0, 16)};
      map (0x1A01, entries, 6);
      assign (0x1C13, tx_default, 2);
      if (go_op (22, (uint16_t)(tx_default_bytes + 12), "0x1A01 with six entries"))
      {
         memset (out, 0, sizeof out);
         esc_sim_cycle (out, 22, in, tx_default_bytes + 12u);
      }
      back_to_preop ();
   }

   printf ("%d failed checks\n", failures);
   return failures == 0 ? 0 : 1;
}
