package org.triad.service;

import java.nio.file.Path;

import org.triad.service.store.TaskStore;

/** A second process that tries to open a service database: prints the start-up error and exits 2, or exits 0. */
public final class LockProbe {
    private LockProbe() {
    }

    public static void main(String[] args) {
        try (TaskStore store = TaskStore.open(Path.of(args[0]))) {
            System.out.println("opened " + store.file());
        } catch (ServiceError e) {
            System.out.println(e.getMessage());
            System.exit(2);
        }
    }
}
