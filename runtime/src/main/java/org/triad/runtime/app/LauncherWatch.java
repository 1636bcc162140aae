package org.triad.runtime.app;

import java.util.Optional;
import java.util.function.Consumer;

/**
 * Ends an application's JVM when the {@code ./triad} process that launched it is gone. The launcher
 * passes its process id as the system property {@value #PROPERTY} and stops its child itself when it
 * exits, is stopped (SIGTERM) or interrupted (SIGINT); only a launcher killed with SIGKILL cannot, and
 * then this watch ends the child, through its shutdown hooks (a robot reports OFFLINE and disconnects),
 * instead of leaving a robot that still acts with nobody to stop it.
 */
public final class LauncherWatch {
    /** The system property naming the launching process's id. */
    public static final String PROPERTY = "triad.launcher.pid";

    private LauncherWatch() {
    }

    /**
     * Starts watching the launcher named by {@value #PROPERTY}, if any; when it ends, reports one line
     * to {@code log} and exits with status 3.
     *
     * @return whether there is a launcher to watch
     */
    public static boolean exitWithLauncher(Consumer<String> log) {
        String pid = System.getProperty(PROPERTY);
        if (pid == null || pid.isBlank()) {
            return false;
        }
        long id;
        try {
            id = Long.parseLong(pid.trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("-D" + PROPERTY + " takes a process id, not '" + pid + "'");
        }
        Optional<ProcessHandle> launcher = ProcessHandle.of(id).filter(ProcessHandle::isAlive);
        Runnable stop = () -> {
            log.accept("triad: the launching process " + id + " is gone; stopping");
            System.exit(3);
        };
        if (launcher.isEmpty()) {
            stop.run();
            return true;
        }
        launcher.get().onExit().thenRun(stop);
        return true;
    }
}
