import { SignInForm } from "@/features/auth/sign-in-form";
import { Card } from "@/ui/surface";

export default function SignInPage() {
  return (
    <main className="flex min-h-full items-center justify-center p-6">
      <Card className="w-full max-w-sm p-8">
        <h1 className="text-2xl font-semibold text-brand-700">HRIStudio</h1>
        <p className="mb-6 mt-1 text-sm text-slate-500">Wizard-of-Oz studies for human-robot interaction</p>
        <SignInForm />
        <p className="mt-6 text-xs text-slate-500">Accounts are created by your lab's administrator.</p>
      </Card>
    </main>
  );
}
