package org.triad.examples.hospital.fleet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** {@code vda5050:URL,...}'s options: a bad value is one line naming the option and what it takes, before any connection. */
class VdaOptionsTest {
    private static String refusal(String argument) {
        return assertThrows(IllegalArgumentException.class, () -> new VdaHospitalFleet().connect(argument, null)).getMessage();
    }

    @Test
    void aSilenceThatIsNotAPositiveNumberOfSecondsIsRefusedWithWhatItTakes() {
        assertEquals("vda5050:...,silence=S takes seconds, not 'soon'", refusal("tcp://127.0.0.1:1,silence=soon"));
        assertEquals("vda5050:...,silence=S takes 0 to 600 seconds, not 0", refusal("tcp://127.0.0.1:1,silence=0"));
        assertEquals("vda5050:...,silence=S takes 0 to 600 seconds, not 601", refusal("tcp://127.0.0.1:1,silence=601"));
    }
}
