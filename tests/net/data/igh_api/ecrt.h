/*
 * The part of the IgH EtherCAT master's application interface (ecrt.h, interface version 1.6)
 * that esi-net's igh_config.h/.c use, declared for the tests from the interface's public
 * documentation (the doxygen pages of ecrt.h and the master's manual, chapter "Application
 * Interface"). Written here, not taken from IgH's sources: the tests compile the generated code
 * against these declarations, so they check that the code uses the documented names, types and
 * argument lists; they cannot check it against a header of a release they do not have. Run the
 * generated files against a real master by hand as docs/esi-net.md ("IgH") says.
 *
 * Layouts and values restated from the documentation:
 *  - the master, slave configuration and domain are opaque types the application only points to;
 *  - ec_direction_t: EC_DIR_INVALID, EC_DIR_OUTPUT (values written by the master), EC_DIR_INPUT
 *    (values read by the master), EC_DIR_COUNT, in that order;
 *  - ec_watchdog_mode_t: EC_WD_DEFAULT (the slave's default), EC_WD_ENABLE, EC_WD_DISABLE;
 *  - ec_pdo_entry_info_t {index, subindex, bit_length}, ec_pdo_info_t {index, n_entries,
 *    entries}, ec_sync_info_t {index, dir, n_pdos, pdos, watchdog_mode}, ec_pdo_entry_reg_t
 *    {alias, position, vendor_id, product_code, index, subindex, offset, bit_position}: the
 *    field order the documentation gives, which positional initialisers depend on;
 *  - EC_END (~0U) ends a sync-info list where the count is not given;
 *  - EC_HAVE_SYNC_TO: the interface has ecrt_master_sync_reference_clock_to() (since 1.5.2).
 */
#ifndef LIBESI_TEST_IGH_ECRT_H
#define LIBESI_TEST_IGH_ECRT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define EC_HAVE_SYNC_TO
#define EC_END ~0U

struct ec_master;
typedef struct ec_master ec_master_t;
struct ec_slave_config;
typedef struct ec_slave_config ec_slave_config_t;
struct ec_domain;
typedef struct ec_domain ec_domain_t;

typedef enum {
    EC_DIR_INVALID,
    EC_DIR_OUTPUT,
    EC_DIR_INPUT,
    EC_DIR_COUNT
} ec_direction_t;

typedef enum {
    EC_WD_DEFAULT,
    EC_WD_ENABLE,
    EC_WD_DISABLE
} ec_watchdog_mode_t;

typedef struct {
    uint16_t index;
    uint8_t subindex;
    uint8_t bit_length;
} ec_pdo_entry_info_t;

typedef struct {
    uint16_t index;
    unsigned int n_entries;
    ec_pdo_entry_info_t const *entries;
} ec_pdo_info_t;

typedef struct {
    uint8_t index;
    ec_direction_t dir;
    unsigned int n_pdos;
    ec_pdo_info_t const *pdos;
    ec_watchdog_mode_t watchdog_mode;
} ec_sync_info_t;

typedef struct {
    uint16_t alias;
    uint16_t position;
    uint32_t vendor_id;
    uint32_t product_code;
    uint16_t index;
    uint8_t subindex;
    unsigned int *offset;
    unsigned int *bit_position;
} ec_pdo_entry_reg_t;

/* Master */
ec_slave_config_t *ecrt_master_slave_config(ec_master_t *master, uint16_t alias, uint16_t position, uint32_t vendor_id,
                                             uint32_t product_code);
int ecrt_master_select_reference_clock(ec_master_t *master, ec_slave_config_t *sc);
int ecrt_master_activate(ec_master_t *master);
int ecrt_master_send(ec_master_t *master);
int ecrt_master_receive(ec_master_t *master);
int ecrt_master_application_time(ec_master_t *master, uint64_t app_time);
int ecrt_master_sync_reference_clock(ec_master_t *master);
int ecrt_master_sync_reference_clock_to(ec_master_t *master, uint64_t sync_time);
int ecrt_master_sync_slave_clocks(ec_master_t *master);

/* Slave configuration */
int ecrt_slave_config_pdos(ec_slave_config_t *sc, unsigned int n_syncs, const ec_sync_info_t syncs[]);
int ecrt_slave_config_watchdog(ec_slave_config_t *sc, uint16_t watchdog_divider, uint16_t watchdog_intervals);
int ecrt_slave_config_sdo(ec_slave_config_t *sc, uint16_t index, uint8_t subindex, const uint8_t *data, size_t size);
int ecrt_slave_config_sdo8(ec_slave_config_t *sc, uint16_t index, uint8_t subindex, uint8_t value);
int ecrt_slave_config_sdo16(ec_slave_config_t *sc, uint16_t index, uint8_t subindex, uint16_t value);
int ecrt_slave_config_sdo32(ec_slave_config_t *sc, uint16_t index, uint8_t subindex, uint32_t value);
int ecrt_slave_config_complete_sdo(ec_slave_config_t *sc, uint16_t index, const uint8_t *data, size_t size);
int ecrt_slave_config_dc(ec_slave_config_t *sc, uint16_t assign_activate, uint32_t sync0_cycle, int32_t sync0_shift,
                         uint32_t sync1_cycle, int32_t sync1_shift);

/* Domain */
int ecrt_domain_reg_pdo_entry_list(ec_domain_t *domain, const ec_pdo_entry_reg_t *pdo_entry_regs);
void ecrt_domain_process(ec_domain_t *domain);
void ecrt_domain_queue(ec_domain_t *domain);
uint8_t *ecrt_domain_data(ec_domain_t *domain);

#ifdef __cplusplus
}
#endif

#endif
