package org.gradle.launcher;

import java.io.File;
import java.util.Arrays;
import java.util.Properties;

import org.gradle.api.internal.StartParameterInternal;
import org.gradle.api.internal.file.FileCollectionFactory;
import org.gradle.api.internal.tasks.userinput.UserInputReader;
import org.gradle.api.logging.LogLevel;
import org.gradle.cli.CommandLineParser;
import org.gradle.cli.ParsedCommandLine;
import org.gradle.configuration.GradleLauncherMetaData;
import org.gradle.initialization.DefaultBuildCancellationToken;
import org.gradle.initialization.NoOpBuildEventConsumer;
import org.gradle.initialization.layout.BuildLayoutFactory;
import org.gradle.internal.buildprocess.BuildProcessState;
import org.gradle.internal.classpath.ClassPath;
import org.gradle.internal.daemon.client.execution.ClientBuildRequestContext;
import org.gradle.internal.instrumentation.agent.AgentStatus;
import org.gradle.internal.logging.LoggingManagerInternal;
import org.gradle.internal.logging.console.GlobalUserInputReceiver;
import org.gradle.internal.logging.services.LoggingServiceRegistry;
import org.gradle.internal.nativeintegration.services.NativeServices;
import org.gradle.internal.service.ServiceRegistry;
import org.gradle.internal.service.ServiceRegistryBuilder;
import org.gradle.internal.service.scopes.BasicGlobalScopeServices;
import org.gradle.internal.service.scopes.Scope;
import org.gradle.launcher.cli.BuildEnvironmentConfigurationConverter;
import org.gradle.launcher.cli.Parameters;
import org.gradle.launcher.daemon.configuration.DaemonParameters;
import org.gradle.launcher.exec.BuildActionResult;
import org.gradle.launcher.exec.BuildExecutor;
import org.gradle.launcher.exec.DefaultBuildActionParameters;
import org.gradle.tooling.internal.provider.ForwardStdInToThisProcess;
import org.gradle.tooling.internal.provider.RunInProcess;
import org.gradle.tooling.internal.provider.action.ExecuteBuildAction;

/**
 * The entry point of the module {@code gradle-gradle-cli}, which {@code dev.gradleplugins:gradle-api}
 * lacks: {@code GradleMain} bootstraps Gradle's class loaders and calls {@link #run}. Parses the command
 * line with Gradle's own converters and runs the build in this JVM, as Gradle's {@code --no-daemon}
 * does when the JVM fits (there is no daemon to start: its entry point is not in gradle-api either).
 */
public class Main {
	public void run(String[] args) {
		// Gradle's logging owns System.err once started: a failure before the build reports itself goes to the raw stream
		java.io.PrintStream raw = new java.io.PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.err), true);
		try {
			doRun(args);
		} catch (Throwable t) {
			t.printStackTrace(raw);
			System.exit(3);
		}
	}

	private void doRun(String[] args) {
		ServiceRegistry logging = LoggingServiceRegistry.newCommandLineProcessLogging();
		LoggingManagerInternal loggingManager = logging.getFactory(LoggingManagerInternal.class).create();
		loggingManager.setLevelInternal(LogLevel.LIFECYCLE);
		loggingManager.start();
		// native services live in the user home, which must be known before the command line is parsed
		String env = System.getenv("GRADLE_USER_HOME");
		File userHome = env != null ? new File(env) : new File(System.getProperty("user.home"), ".gradle");
		for (int i = 0; i < args.length - 1; i++) {
			if (args[i].equals("-g") || args[i].equals("--gradle-user-home")) {
				userHome = new File(args[i + 1]).getAbsoluteFile();
			}
		}
		NativeServices.initializeOnClient(userHome, NativeServices.NativeServicesMode.fromSystemProperties());
		ServiceRegistry basic = ServiceRegistryBuilder.builder().scopeStrictly(Scope.Global.class).displayName("Basic global services")
				.parent(logging).parent(NativeServices.getInstance()).provider(new BasicGlobalScopeServices()).build();
		CommandLineParser parser = new CommandLineParser();
		BuildEnvironmentConfigurationConverter converter = new BuildEnvironmentConfigurationConverter(new BuildLayoutFactory(),
				basic.get(FileCollectionFactory.class));
		converter.configure(parser);
		Parameters parameters;
		try {
			ParsedCommandLine commandLine = parser.parse(Arrays.asList(args));
			parameters = converter.convertParameters(commandLine, null);
		} catch (org.gradle.cli.CommandLineArgumentException e) {
			System.err.println("gradle: " + e.getMessage());
			System.exit(2);
			return;
		}
		StartParameterInternal startParameter = parameters.getStartParameter();
		DaemonParameters daemonParameters = parameters.getDaemonParameters();
		loggingManager.setLevelInternal(startParameter.getLogLevel());
		loggingManager.attachProcessConsole(startParameter.getConsoleOutput());
		Properties properties = new Properties();
		properties.putAll(daemonParameters.getEffectiveSystemProperties());
		System.setProperties(properties);
		BuildProcessState state = new BuildProcessState(startParameter.isContinuous(), AgentStatus.disabled(), ClassPath.EMPTY, logging,
				NativeServices.getInstance());
		ServiceRegistry global = state.getServices();
		RunInProcess executor = new RunInProcess(new ForwardStdInToThisProcess(global.get(GlobalUserInputReceiver.class),
				global.get(UserInputReader.class), System.in, global.get(BuildExecutor.class)));
		BuildActionResult result;
		try {
			result = executor.execute(new ExecuteBuildAction(startParameter),
					new DefaultBuildActionParameters(daemonParameters.getEffectiveSystemProperties(), daemonParameters.getEnvironmentVariables(),
							new File(System.getProperty("user.dir")), startParameter.getLogLevel(), false, ClassPath.EMPTY),
					new ClientBuildRequestContext(new GradleLauncherMetaData(), System.currentTimeMillis(), false, new DefaultBuildCancellationToken(),
							new NoOpBuildEventConsumer()));
		} finally {
			state.close();
			loggingManager.stop();
		}
		System.exit(result.hasFailure() ? 1 : 0);
	}
}
