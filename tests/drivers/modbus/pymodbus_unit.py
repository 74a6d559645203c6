#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""An independent pan/tilt unit for the Modbus driver's tests: python3-pymodbus serves the custom
test map (tests/drivers/modbus/modbus_rig.hpp: slaves 1 and 2, velocity at 0..1, actual position
at 10..11 as 32 bit high word first, status at 20) and logs every register write it receives.

usage: pymodbus_unit.py PORT LOGFILE
The actual position of slave 1 is 12345 counts and of slave 2 is -6789, packed here with struct,
so a misreading of word or byte order shows on either side. Log lines: time_s,slave,register,value
(time.monotonic(), the clock raysd's steady_clock reads).
"""
import struct
import sys
import time

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server import StartTcpServer


class LoggingBlock(ModbusSequentialDataBlock):
    def __init__(self, slave, log, position):
        super().__init__(0, [0] * 200)
        self.slave = slave
        self.log = log
        high, low = struct.unpack(">HH", struct.pack(">i", position))
        super().setValues(10, [high, low])

    def setValues(self, address, values):  # noqa: N802 (pymodbus's name)
        super().setValues(address, values)
        if not isinstance(values, list):
            values = [values]
        for offset, value in enumerate(values):
            self.log.write(f"{time.monotonic():.6f},{self.slave},{address + offset},{value},\n")
        self.log.flush()


def main():
    port = int(sys.argv[1])
    log = open(sys.argv[2], "w", encoding="ascii")
    log.write("time_s,slave,register,value,note\n")
    log.flush()
    slaves = {}
    for slave, position in ((1, 12345), (2, -6789)):
        # zero_mode: register N on the wire is entry N of the block (no +1 shift).
        slaves[slave] = ModbusSlaveContext(hr=LoggingBlock(slave, log, position), zero_mode=True)
    StartTcpServer(context=ModbusServerContext(slaves=slaves, single=False), address=("127.0.0.1", port))


if __name__ == "__main__":
    main()
