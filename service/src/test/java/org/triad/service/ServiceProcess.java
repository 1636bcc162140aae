package org.triad.service;

import java.util.Arrays;
import java.util.Map;

/**
 * A service in a process of its own, for tests that kill it: {@code ServiceProcess DB ROBOTS...}
 * prints {@code listening URL} once it serves, or the start-up error and exits 2.
 */
public final class ServiceProcess {
    private ServiceProcess() {
    }

    public static void main(String[] args) throws InterruptedException {
        TriadService service;
        try {
            service = TriadService.start(new TriadService.Options(ServiceFixture.HOSPITAL, Arrays.asList(args).subList(1, args.length), null, args[0],
                    null, "127.0.0.1", 0, Map.of(AccessTokens.SUBMIT_ENV, ServiceFixture.SUBMIT, AccessTokens.OPERATOR_ENV, ServiceFixture.OPERATOR)));
        } catch (ServiceError e) {
            System.out.println("startup error: " + e.getMessage());
            System.out.flush();
            System.exit(2);
            return;
        }
        System.out.println("listening " + service.url());
        System.out.flush();
        Thread.currentThread().join();
    }
}
