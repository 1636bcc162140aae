/**
 * The messages of VDA 5050 2.1 (order, instantActions, state, connection, visualization, factsheet) as
 * Java records that Jackson writes and reads with the field names of the official JSON schemas, their
 * topics ({@code uagv/v2/{manufacturer}/{serialNumber}/{topic}}), header ids, and validation of every
 * message against the official schemas ({@link org.triad.vda5050.protocol.MessageSchemas}).
 */
package org.triad.vda5050.protocol;
