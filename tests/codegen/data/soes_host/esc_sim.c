/*
 * A simulated EtherCAT slave controller: SOES's hardware layer over an array, and the master's
 * side of the conversation (esc_sim.h). Written for the host tests of the generated SOES set;
 * it models only what SOES reads and writes.
 */
#include "esc_sim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ecat_slv.h"
#include "esc.h"
#include "esc_eep.h"

uint8_t esc_sim_memory[ESC_SIM_SIZE];

#define SM_STATUS_MAILBOX_FULL 0x08u
#define SM_REGISTER(n) ((uint16_t)(ESCREG_SM0 + 8u * (n)))

static uint8_t mailbox_counter;

static uint16_t get16 (uint32_t address)
{
   return (uint16_t)(esc_sim_memory[address] | (esc_sim_memory[address + 1u] << 8));
}

static void put16 (uint32_t address, uint16_t value)
{
   esc_sim_memory[address] = (uint8_t)(value & 0xFFu);
   esc_sim_memory[address + 1u] = (uint8_t)(value >> 8);
}

static void set_event (uint16_t bits) { put16 (ESCREG_ALEVENT, (uint16_t)(get16 (ESCREG_ALEVENT) | bits)); }
static void clear_event (uint16_t bits) { put16 (ESCREG_ALEVENT, (uint16_t)(get16 (ESCREG_ALEVENT) & ~bits)); }

static void check_range (const char * what, uint16_t address, uint16_t len)
{
   if ((uint32_t)address + len > ESC_SIM_SIZE)
   {
      fprintf (stderr, "esc_sim: %s of %u bytes at 0x%04X runs past the ESC\n", what, len, address);
      abort ();
   }
}

static int covers (uint16_t address, uint16_t len, uint32_t byte)
{
   return byte >= address && byte < (uint32_t)address + len;
}

/* SOES hardware layer (esc.h) */

void ESC_read (uint16_t address, void * buf, uint16_t len)
{
   check_range ("ESC_read", address, len);
   memcpy (buf, &esc_sim_memory[address], len);
   /* Reading AL control acknowledges the AL control event. */
   if (covers (address, len, ESCREG_ALCONTROL)) clear_event (ESCREG_ALEVENT_CONTROL);
   /* Reading the last byte of the receive mailbox empties it. */
   if (covers (address, len, MBX0_sma + MBX0_sml - 1u))
   {
      esc_sim_memory[ESCREG_SM0STATUS] &= (uint8_t)~SM_STATUS_MAILBOX_FULL;
      clear_event (ESCREG_ALEVENT_SM0);
   }
   /* Like the ET1100 (and SOES's own LAN9252 layer), every access refreshes the AL event. */
   ESCvar.ALevent = get16 (ESCREG_ALEVENT);
}

void ESC_write (uint16_t address, void * buf, uint16_t len)
{
   check_range ("ESC_write", address, len);
   memcpy (&esc_sim_memory[address], buf, len);
   /* Writing the last byte of the send mailbox fills it for the master. */
   if (covers (address, len, MBX1_sma + MBX1_sml - 1u))
      esc_sim_memory[SM_REGISTER (1) + 5u] |= SM_STATUS_MAILBOX_FULL;
   ESCvar.ALevent = get16 (ESCREG_ALEVENT);
}

void ESC_init (const esc_cfg_t * config) { (void)config; }

void ESC_reset (void) {}

/* No emulated EEPROM: the SII is the master's business here. */
int8_t EEP_read (uint32_t addr, uint8_t * data, uint16_t size)
{
   (void)addr;
   memset (data, 0xFF, size);
   return 0;
}

int8_t EEP_write (uint32_t addr, uint8_t * data, uint16_t size)
{
   (void)addr;
   (void)data;
   (void)size;
   return 0;
}

/* The master's side */

static void configure_sm (uint8_t n, uint16_t start, uint16_t length, uint8_t control, uint8_t activate)
{
   const uint16_t r = SM_REGISTER (n);
   put16 (r, start);
   put16 (r + 2u, length);
   esc_sim_memory[r + 4u] = control;
   esc_sim_memory[r + 5u] = 0;
   esc_sim_memory[r + 6u] = activate;
}

void esc_sim_reset (void)
{
   memset (esc_sim_memory, 0, sizeof esc_sim_memory);
   esc_sim_memory[ESCREG_DLSTATUS] = 0x01; /* PDI operational */
   esc_sim_memory[ESCREG_ALSTATUS] = ESCinit;
   configure_sm (0, MBX0_sma, MBX0_sml, MBX0_smc, 1);
   configure_sm (1, MBX1_sma, MBX1_sml, MBX1_smc, 1);
   mailbox_counter = 0;
}

void esc_sim_configure_pdo_sm (uint8_t sm, uint16_t length)
{
   if (sm == 2) configure_sm (2, SM2_sma, length, SM2_smc, length > 0 ? 1 : 0);
   else configure_sm (3, SM3_sma, length, SM3_smc, length > 0 ? 1 : 0);
}

uint8_t esc_sim_request_state (uint8_t state)
{
   const uint8_t status = esc_sim_memory[ESCREG_ALSTATUS];
   /* A state request after a refusal acknowledges the error. */
   put16 (ESCREG_ALCONTROL, (uint16_t)(state | (status & ESCerror)));
   set_event (ESCREG_ALEVENT_CONTROL);
   ecat_slv_poll ();
   clear_event (ESCREG_ALEVENT_CONTROL);
   return esc_sim_memory[ESCREG_ALSTATUS];
}

/* Sends one CoE SDO request (command, index, subindex, 4 data bytes) and returns the response's
 * command byte, its data in *data; 0 when the stack did not answer. */
static uint8_t sdo_exchange (uint8_t command, uint16_t index, uint8_t subindex, uint32_t data_out, uint32_t * data_in)
{
   uint8_t frame[16] = {0};
   uint32_t i;
   const uint32_t request = MBX0_sma;
   const uint32_t response = MBX1_sma;

   mailbox_counter = (uint8_t)(mailbox_counter % 7u + 1u);
   frame[0] = 10; /* mailbox header: length of what follows it */
   frame[5] = (uint8_t)(MBXCOE | (mailbox_counter << 4));
   frame[7] = (uint8_t)(COE_SDOREQUEST << 4); /* CoE header: service in bits 12-15 */
   frame[8] = command;
   frame[9] = (uint8_t)(index & 0xFFu);
   frame[10] = (uint8_t)(index >> 8);
   frame[11] = subindex;
   for (i = 0; i < 4; i++) frame[12 + i] = (uint8_t)(data_out >> (8 * i));
   memset (&esc_sim_memory[request], 0, MBX0_sml);
   memcpy (&esc_sim_memory[request], frame, sizeof frame);
   esc_sim_memory[ESCREG_SM0STATUS] |= SM_STATUS_MAILBOX_FULL;
   set_event (ESCREG_ALEVENT_SM0);

   for (i = 0; i < 8 && (esc_sim_memory[SM_REGISTER (1) + 5u] & SM_STATUS_MAILBOX_FULL) == 0; i++) ecat_slv_poll ();
   if ((esc_sim_memory[SM_REGISTER (1) + 5u] & SM_STATUS_MAILBOX_FULL) == 0) return 0;

   *data_in = 0;
   for (i = 0; i < 4; i++) *data_in |= (uint32_t)esc_sim_memory[response + 12u + i] << (8 * i);
   command = esc_sim_memory[response + 8u];
   /* The master reads the send mailbox: it empties, and the slave sees the SM1 event. */
   esc_sim_memory[SM_REGISTER (1) + 5u] &= (uint8_t)~SM_STATUS_MAILBOX_FULL;
   set_event (ESCREG_ALEVENT_SM1);
   ecat_slv_poll ();
   clear_event (ESCREG_ALEVENT_SM1);
   return command;
}

uint32_t esc_sim_sdo_download (uint16_t index, uint8_t subindex, uint32_t value, uint8_t size)
{
   uint32_t answer = 0;
   const uint8_t command = (uint8_t)(COE_COMMAND_DOWNLOADREQUEST | COE_EXPEDITED_INDICATOR | COE_SIZE_INDICATOR |
                                     ((4u - size) << 2));
   const uint8_t reply = sdo_exchange (command, index, subindex, value, &answer);
   if (reply == COE_COMMAND_DOWNLOADRESPONSE) return 0;
   if (reply == COE_COMMAND_SDOABORT) return answer;
   return 0xFFFFFFFFu;
}

uint32_t esc_sim_sdo_upload (uint16_t index, uint8_t subindex, uint32_t * value)
{
   uint32_t answer = 0;
   const uint8_t reply = sdo_exchange (COE_COMMAND_UPLOADREQUEST, index, subindex, 0, &answer);
   if (reply == COE_COMMAND_SDOABORT) return answer;
   if ((reply & 0xE0u) != COE_COMMAND_UPLOADRESPONSE) return 0xFFFFFFFFu;
   *value = answer;
   return 0;
}

void esc_sim_cycle (const uint8_t * outputs, size_t output_bytes, uint8_t * inputs, size_t input_bytes)
{
   memcpy (&esc_sim_memory[SM2_sma], outputs, output_bytes);
   set_event (ESCREG_ALEVENT_SM2);
   /* The SM2 event as the application's interrupt or poll loop reads it before DIG_process. */
   ESCvar.ALevent = get16 (ESCREG_ALEVENT);
   DIG_process (DIG_PROCESS_OUTPUTS_FLAG | DIG_PROCESS_INPUTS_FLAG);
   clear_event (ESCREG_ALEVENT_SM2);
   memcpy (inputs, &esc_sim_memory[SM3_sma], input_bytes);
}
