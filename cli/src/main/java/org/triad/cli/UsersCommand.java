package org.triad.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.concurrent.Callable;

import org.triad.service.ServiceError;
import org.triad.service.TriadService;
import org.triad.service.auth.Role;
import org.triad.service.auth.UserStore;
import org.triad.service.store.TaskStore;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code triad users DIR add|list|revoke}: the service's named users, in its database, while the service is stopped. */
@Command(name = "users", mixinStandardHelpOptions = true,
		description = { "Manage the named users of ./triad serve (roles staff, operator, admin) in its database: add prints the new",
				"user's token once (only a bcrypt hash is kept), list shows every user, revoke refuses a user's token from now on.",
				"Works on whatever a previous start left (it creates and migrates the database as the service does); the service",
				"must be stopped (its database is locked while it runs: use the admin API /api/users then).",
				"Exit code 2 for a bad name or role, an unknown user or a database in use." })
public final class UsersCommand implements Callable<Integer> {
	@Parameters(index = "0", paramLabel = "DIR", description = "the application's folder, as for serve (its database DIR/" + TriadService.DEFAULT_DB + ")")
	private Path dir;

	@Parameters(index = "1", paramLabel = "ACTION", description = "add, list or revoke")
	private String action;

	@Parameters(index = "2", arity = "0..1", paramLabel = "NAME", description = "the user (add, revoke)")
	private String name;

	@Option(names = "--role", paramLabel = "ROLE", description = "staff, operator or admin (add; default: ${DEFAULT-VALUE})")
	private String role = "staff";

	@Option(names = "--db", paramLabel = "FILE", description = "the database (default DIR/" + TriadService.DEFAULT_DB + ".mv.db), as for serve")
	private Path db;

	@CommandLine.Spec
	private CommandLine.Model.CommandSpec spec;

	@Override
	public Integer call() {
		PrintWriter out = spec.commandLine().getOut();
		if (!Files.isDirectory(dir)) {
			throw new ModelSession.UserError("no folder " + dir);
		}
		if (!action.equals("list") && name == null) {
			throw new ModelSession.UserError(action + " needs the user's NAME");
		}
		Path file = db != null ? db : dir.resolve(TriadService.DEFAULT_DB);
		try (TaskStore store = TaskStore.open(file)) {
			UserStore users = new UserStore(store);
			switch (action) {
				case "add" -> {
					String token = users.add(name, Role.of(role), Instant.now());
					out.println("user " + name + " (" + role + ") added; the token, shown only now: " + token);
				}
				case "list" -> {
					for (UserStore.User u : users.list()) {
						out.println(u.name() + "\t" + u.role() + "\tadded " + u.created() + (u.revoked() != null ? "\trevoked " + u.revoked() : ""));
					}
				}
				case "revoke" -> {
					if (!users.revoke(name, Instant.now())) {
						throw new ModelSession.UserError("no user '" + name + "' to revoke (unknown or revoked already)");
					}
					out.println("user " + name + " revoked");
				}
				default -> throw new ModelSession.UserError("ACTION is add, list or revoke, not '" + action + "'");
			}
		} catch (ServiceError | IllegalArgumentException e) {
			throw new ModelSession.UserError(e.getMessage());
		}
		out.flush();
		return 0;
	}
}
