package org.triad.vda5050.protocol;

/** The fields every VDA 5050 message starts with; implemented by each message record. */
public interface Header {
    /** The protocol version Triad speaks. */
    String VERSION = "2.1.0";
    /** The major version, as it appears in topics ({@code uagv/v2/...}). */
    String MAJOR = "v2";

    int headerId();

    String timestamp();

    String version();

    String manufacturer();

    String serialNumber();

    /** The major version number of {@code version}, e.g. 2 for {@code 2.1.0}; -1 if it is not a version. */
    static int majorOf(String version) {
        if (version == null) {
            return -1;
        }
        int dot = version.indexOf('.');
        try {
            return Integer.parseInt(dot < 0 ? version : version.substring(0, dot));
        } catch (NumberFormatException e) {
            return -1;
        }
    }
}
