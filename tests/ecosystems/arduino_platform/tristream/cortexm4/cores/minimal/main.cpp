// SPDX-License-Identifier: MIT
// The minimal core's program: setup() once, loop() once, and Serial through stdio.
#include <stdio.h>
#include <time.h>

#include "Arduino.h"

SerialPort Serial;

void SerialPort::begin(unsigned long) {}
void SerialPort::print(const char* text) { fputs(text, stdout); }
void SerialPort::print(long value, int base) { printf(base == HEX ? "%lX" : "%ld", value); }
void SerialPort::print(unsigned long value, int base) { printf(base == HEX ? "%lX" : "%lu", value); }

unsigned long millis(void) { return static_cast<unsigned long>(clock()) * 1000ul / CLOCKS_PER_SEC; }

int main() {
  setup();
  loop();
  return 0;
}
