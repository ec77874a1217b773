/*
 * A host program around a generated SOES set (objectlist.c, utypes.h, ecat_options.h) and the
 * real SOES core, on the simulated ESC of esc_sim.c: the stack starts, goes Init -> PreOp ->
 * SafeOp -> Op with the device's default PDO assignment and runs one process-data cycle. It
 * prints the state reached and the process-image sizes SOES computed from the object list.
 */
#include <stdio.h>

#include "ecat_slv.h"
#include "esc_sim.h"
#include "utypes.h"

_Objects Obj;

void cb_get_inputs (void) {}
void cb_set_outputs (void) {}

int main (void)
{
   static esc_cfg_t config; /* every hook NULL, polling */
   uint8_t outputs[MAX_RXPDO_SIZE] = {0};
   uint8_t inputs[MAX_TXPDO_SIZE] = {0};
   uint8_t state;

   esc_sim_reset ();
   ecat_slv_init (&config);
   state = esc_sim_request_state (ESCpreop);
   if (state != ESCpreop)
   {
      printf ("PreOp refused: AL status 0x%02X\n", state);
      return 1;
   }
   /* The first SafeOp request computes the process image; the master then sets the
    * SyncManagers to the sizes the device reports, as from its SII or ESI. */
   esc_sim_request_state (ESCsafeop);
   esc_sim_configure_pdo_sm (2, ESCvar.ESC_SM2_sml);
   esc_sim_configure_pdo_sm (3, ESCvar.ESC_SM3_sml);
   state = esc_sim_request_state (ESCsafeop);
   if (state == ESCsafeop) state = esc_sim_request_state (ESCop);
   if (state == ESCop) esc_sim_cycle (outputs, ESCvar.ESC_SM2_sml, inputs, ESCvar.ESC_SM3_sml);
   printf ("state 0x%02X sm2 %u sm3 %u\n", state, ESCvar.ESC_SM2_sml, ESCvar.ESC_SM3_sml);
   return state == ESCop ? 0 : 1;
}
