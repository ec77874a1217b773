/*
 * A simulated EtherCAT slave controller for running the real SOES stack on the build host
 * (tests/codegen/soes_stack_test.cpp). esc_sim.c implements SOES's hardware layer (ESC_read,
 * ESC_write, ESC_init, ESC_reset over a 64 KiB register and DPRAM image) and plays the master's
 * side: state requests through AL control, SDO transfers through the standard mailbox, process
 * data through the SyncManager 2/3 buffers.
 *
 * Register behaviour follows the Beckhoff "EtherCAT Slave Controller" data sheet, section II:
 * reading AL control (0x0120) clears the AL control event, reading the last byte of a
 * master-written mailbox empties it, writing the last byte of the slave's mailbox fills it.
 */
#ifndef ESC_SIM_H
#define ESC_SIM_H

#include <stddef.h>
#include <stdint.h>

/* The whole ESC address space; SOES accesses outside it abort the program. */
#define ESC_SIM_SIZE 0x10000u

extern uint8_t esc_sim_memory[ESC_SIM_SIZE];

/* Clears the ESC, marks the PDI operational and configures the standard mailbox SyncManagers
 * the way ecat_options.h states them (as a master does from the SII). */
void esc_sim_reset (void);

/* Configures SyncManager 2 or 3 (process data) with `length` bytes, as a master does before
 * requesting SafeOp. */
void esc_sim_configure_pdo_sm (uint8_t sm, uint16_t length);

/* Requests an AL state (0x01 Init, 0x02 PreOp, 0x04 SafeOp, 0x08 Op), runs the stack and returns
 * the AL status it answers with (the error bit 0x10 set when it refused). */
uint8_t esc_sim_request_state (uint8_t state);

/* An expedited SDO download of 1, 2 or 4 bytes; returns 0 or the SDO abort code. */
uint32_t esc_sim_sdo_download (uint16_t index, uint8_t subindex, uint32_t value, uint8_t size);

/* An expedited SDO upload; returns 0 or the abort code, the value in *value. */
uint32_t esc_sim_sdo_upload (uint16_t index, uint8_t subindex, uint32_t * value);

/* One cycle of process data in Op: `outputs` (`output_bytes`) into SM2, the stack's DIG_process,
 * then `input_bytes` out of SM3 into `inputs`. */
void esc_sim_cycle (const uint8_t * outputs, size_t output_bytes, uint8_t * inputs, size_t input_bytes);

#endif /* ESC_SIM_H */
